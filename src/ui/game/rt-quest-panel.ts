import { msg, str } from '@lit/localize';
import { css, html, nothing, type PropertyValues } from 'lit';
import { LocalizedElement } from '../controls/localized-element.ts';
import type { Locale } from '../../quest/localized-text.ts';
import type { LevelView } from '../../quest/level-view.ts';
import { plainLevelText } from '../../quest/text-markup.ts';
import { explainMore } from './explain-more.ts';
import { fire, gameStyles } from './game-styles.ts';
import { levelText } from './level-text.ts';
import { QUEST_COMMAND, type QuestCommand } from './quest-command.ts';
import './rt-task-card.ts';
import { scrollBoxToTop, scrollInBox } from './scroll-in-box.ts';
import { type TaskFocus, type TaskScroll, taskScroll } from './task-scroll.ts';

/**
 * @summary The task column of a level: its title and intro (with "Explain more"), the
 * celebration once the level is passed (points, badges, "Next level"), and the task list
 * with the current task open. A prediction whose result the learner has just observed opens
 * again, in place of the current task, until they continue from its explanation. Back in a
 * passed level, a note says its scene started afresh.
 *
 * @fires quest-command - everything the learner asks (QuestCommand).
 */
export class RtQuestPanel extends LocalizedElement {
  static override properties = {
    view: { attribute: false },
    locale: {},
    hasNextLevel: { type: Boolean, attribute: 'has-next-level' },
    badges: { attribute: false },
    returned: { state: true },
  };
  static override styles = [
    gameStyles,
    css`
      :host {
        display: flex;
        flex-direction: column;
        gap: 10px;
        color: var(--rt-text);
      }
      h2 {
        font-size: 1.1rem;
      }
      .level-points {
        font-size: 0.8125rem;
      }
      ol {
        display: flex;
        flex-direction: column;
        gap: 6px;
        margin: 0;
        padding: 0;
        list-style: none;
      }
      rt-task-card {
        display: block;
      }
      .celebration {
        border: 2px solid var(--rt-success);
        background: color-mix(in srgb, var(--rt-success) 10%, var(--rt-surface));
      }
      .celebration h3 {
        font-size: 1.05rem;
      }
      .celebration ul {
        margin: 0 0 8px;
        padding-left: 1.2em;
      }
      .actions {
        display: flex;
        flex-wrap: wrap;
        gap: 8px;
      }
      .celebration .actions:not(:last-child) {
        margin-bottom: 8px;
      }
    `,
  ];

  declare view: LevelView | null;
  declare locale: Locale;
  declare hasNextLevel: boolean;
  /** Names of the badges earned in this level. */
  declare badges: string[];
  /** The level was already passed when it was opened: its scene is the level's own again. */
  declare private returned: boolean;
  /** The level and the current task (or revealed prediction) last brought into view. */
  private shown: TaskFocus = { level: null, task: null };
  /** The scroll asked for while the panel was hidden, done once it is shown. */
  private pendingScroll: TaskScroll | null = null;
  private readonly shownWatch = new ResizeObserver(() => {
    if (this.pendingScroll === null || this.getClientRects().length === 0) return;
    this.bringIntoView(this.pendingScroll);
    this.pendingScroll = null;
  });

  constructor() {
    super();
    this.view = null;
    this.locale = 'en';
    this.hasNextLevel = false;
    this.badges = [];
    this.returned = false;
  }

  protected override willUpdate(changed: PropertyValues<this>): void {
    if (changed.has('view') && changed.get('view')?.level.id !== this.view?.level.id) {
      // Said only when true: a level reopened where the learner left it keeps its scene.
      this.returned = (this.view?.passed ?? false) && !this.view?.sceneKept;
    }
  }

  override connectedCallback(): void {
    super.connectedCallback();
    this.shownWatch.observe(this);
  }

  override disconnectedCallback(): void {
    super.disconnectedCallback();
    this.shownWatch.disconnect();
  }

  protected override updated(): void {
    const view = this.view;
    const now: TaskFocus = { level: view?.level.id ?? null, task: (view?.revealing ?? view?.current)?.task.id ?? null };
    const scroll = taskScroll(this.shown, now);
    this.shown = now;
    if (scroll.kind === 'stay') return;
    // Hidden (a small screen's column shows the panels instead), nothing can be measured or
    // scrolled: it is done when the tasks are shown again.
    if (this.getClientRects().length === 0) this.pendingScroll = scroll;
    else this.bringIntoView(scroll);
  }

  private bringIntoView(scroll: TaskScroll): void {
    if (scroll.kind === 'top') {
      // A level opens at its title, with nothing of the page left selected from the last one.
      document.getSelection()?.removeAllRanges();
      scrollBoxToTop(this);
    } else if (scroll.kind === 'task') {
      // Done tasks above the current one pushed it below the column's edge. Measured once the
      // cards have drawn their new state (the task opened, the one before folded), before the
      // frame is painted: measured at once, the opened card's top ended above the column's edge.
      const item = this.renderRoot.querySelector(`li[data-task="${scroll.task}"]`);
      if (item) requestAnimationFrame(() => scrollInBox(item));
    }
  }

  override render() {
    const view = this.view;
    if (!view) return nothing;
    const { level } = view;
    const send = (command: QuestCommand) => fire(this, QUEST_COMMAND, command);
    return html`
      <header>
        <h2>${plainLevelText(level.title, this.locale)}</h2>
        <p class="muted level-points">${msg(str`${view.points} of ${view.maxPoints} points`)}</p>
        <p>${levelText(level.intro.text, this.locale)}</p>
        ${level.intro.more ? explainMore(level.intro.more, this.locale, () => send({ kind: 'explain', task: 'intro' })) : nothing}
      </header>
      ${view.passed ? this.celebration(view, send) : nothing}
      <ol aria-label=${msg('Tasks')}>
        ${view.tasks.map(
          (task) => html`<li data-task=${task.task.id}>
            <rt-task-card
              .task=${task}
              locale=${this.locale}
              ?expanded=${task.status === 'current' || task === view.revealing}
            ></rt-task-card>
          </li>`,
        )}
      </ol>
    `;
  }

  private celebration(view: LevelView, send: (command: QuestCommand) => void) {
    return html`<section class="card celebration" role="status" aria-label=${msg('Level complete')}>
      <h3>★ ${msg('Level complete!')}</h3>
      <p>${msg(str`You have ${view.points} of ${view.maxPoints} points in this level.`)}</p>
      ${this.returned ? html`<p class="muted" data-note="returned">${msg('You passed this level before, so it opened with its own scene again: your points and finished tasks are kept.')}</p>` : nothing}
      ${
        this.badges.length > 0
          ? html`<p>${msg('Badges earned:')}</p>
            <ul>
              ${this.badges.map((badge) => html`<li>◆ ${badge}</li>`)}
            </ul>`
          : nothing
      }
      <div class="actions">
        ${this.hasNextLevel ? html`<button class="primary" data-action="next-level" @click=${() => send({ kind: 'next-level' })}>${msg('Next level')}</button>` : nothing}
        <button @click=${() => send({ kind: 'map' })}>${msg('Level map')}</button>
      </div>
      ${view.tasks.some((task) => task.status === 'open') ? html`<p class="muted">${msg('Optional tasks are still open below, for extra points.')}</p>` : nothing}
    </section>`;
  }
}

customElements.define('rt-quest-panel', RtQuestPanel);

declare global {
  interface HTMLElementTagNameMap {
    'rt-quest-panel': RtQuestPanel;
  }
}
