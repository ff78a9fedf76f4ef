import { msg } from '@lit/localize';
import { css, html, nothing } from 'lit';
import { LocalizedElement } from '../controls/localized-element.ts';
import type { Locale } from '../../quest/localized-text.ts';
import type { TaskView } from '../../quest/level-view.ts';
import { fire, gameStyles } from './game-styles.ts';
import { levelText } from './level-text.ts';
import { QUEST_COMMAND, type QuestCommand } from './quest-command.ts';

/**
 * @summary A task's hint ladder: the text hints shown so far, and one button for the next
 * rung, named for what it does ("Hint", "Show me where", "Show me"). After idle time the
 * engine offers the next rung: the same button then says a hint is ready (so a learner
 * whose focus is on it keeps it), and screen readers hear so politely. Only opening it
 * counts as a hint used.
 *
 * @fires quest-command - `hint` or `show-me` for the task.
 */
export class RtHintBox extends LocalizedElement {
  static override properties = { task: { attribute: false }, locale: {} };
  static override styles = [
    gameStyles,
    css`
      button.offer {
        border-color: var(--rt-accent);
        background: var(--rt-accent-soft);
        font-weight: 600;
      }
    `,
  ];

  declare task: TaskView | undefined;
  declare locale: Locale;

  constructor() {
    super();
    this.locale = 'en';
  }

  override render() {
    const view = this.task;
    if (!view) return nothing;
    const id = view.task.id;
    const next = view.nextHint;
    const command: QuestCommand | null = next === 'show-me' ? { kind: 'show-me', task: id } : next ? { kind: 'hint', task: id } : null;
    return html`
      <div aria-live="polite">
        ${view.hints.map((hint, index) => html`<p class="hint"><strong>${msg('Hint')} ${index + 1}:</strong> ${levelText(hint, this.locale)}</p>`)}
        ${view.hintOffered ? html`<p class="visually-hidden">${msg('A hint is ready for you.')}</p>` : nothing}
      </div>
      ${
        command
          ? html`<button class=${view.hintOffered ? 'offer' : ''} data-hint=${next ?? ''} title=${view.hintOffered ? msg('Opening it counts as a hint used; leaving it costs nothing') : this.tooltip(next)} @click=${() => fire(this, QUEST_COMMAND, command)}>
            ${view.hintOffered ? msg('Stuck? A hint is ready — show it') : this.label(view)}
          </button>`
          : nothing
      }
    `;
  }

  private label(view: TaskView): string {
    switch (view.nextHint) {
      case 'text':
        return view.hints.length === 0 ? msg('Hint') : msg('Another hint');
      case 'guidance':
        return msg('Show me where');
      default:
        return msg('Show me');
    }
  }

  private tooltip(next: TaskView['nextHint']): string {
    switch (next) {
      case 'text':
        return msg('A tip in words');
      case 'guidance':
        return msg('A ring shows the control to use');
      default:
        return msg('The app does it for you, step by step (the task then gives no points)');
    }
  }
}

customElements.define('rt-hint-box', RtHintBox);

declare global {
  interface HTMLElementTagNameMap {
    'rt-hint-box': RtHintBox;
  }
}
