import { msg, str } from '@lit/localize';
import { css, html, nothing, type TemplateResult } from 'lit';
import { LocalizedElement } from '../controls/localized-element.ts';
import { predictionOf } from '../../quest/goal.ts';
import type { Locale } from '../../quest/localized-text.ts';
import type { Task } from '../../quest/level-schema.ts';
import type { TaskView } from '../../quest/level-view.ts';
import { plainLevelText } from '../../quest/text-markup.ts';
import { figureUrl } from './figure-urls.ts';
import { explainMore } from './explain-more.ts';
import { fire, gameStyles } from './game-styles.ts';
import { levelText } from './level-text.ts';
import { predictionText } from './prediction-text.ts';
import { foldedPrediction } from './prediction-summary.ts';
import { QUEST_COMMAND, type QuestCommand } from './quest-command.ts';
import './rt-hint-box.ts';
import './rt-quiz.ts';
import './rt-challenge.ts';
import { codeLabPanel } from './code-lab/code-lab-panel.ts';

/**
 * @summary One task in the task list: a status mark (in words for screen readers, as a
 * symbol for the eye), its title and points; expanded, its figure, its instruction, "Explain
 * more", the quiz or the Next button, and the hint ladder. Optional tasks can be skipped.
 * An optional task opens on a click; a prediction the learner has seen explained folds to a
 * line with what they expected and the answer (prediction-summary.ts), and opens on a click.
 *
 * Reflects `status` (current, open, waiting, done, shown, skipped) and `data-task` (the
 * task's id) as attributes.
 *
 * @fires quest-command - next, skip, explain (and, from inside, hint, show-me, answer).
 */
export class RtTaskCard extends LocalizedElement {
  static override properties = { task: { attribute: false }, locale: {}, expanded: { type: Boolean, reflect: true }, opened: { state: true } };
  static override styles = [
    gameStyles,
    css`
      :host {
        border: 1px solid var(--rt-border);
        border-radius: var(--rt-radius);
        background: var(--rt-surface);
      }
      :host([status='current']) {
        border: 2px solid var(--rt-accent);
        box-shadow: var(--rt-shadow);
      }
      button.head {
        width: 100%;
        border: 0;
        background: none;
        text-align: left;
      }
      .head {
        display: flex;
        align-items: center;
        gap: 8px;
        min-height: 36px;
        padding: 2px 10px;
      }
      .mark {
        flex: none;
        width: 1.4em;
        text-align: center;
        font-weight: 700;
      }
      /* A title that does not fit on one line beside its tags moves them to a line of their
         own (right-aligned): a long Dutch title beside two tags was squeezed into a column a
         word wide. */
      .label {
        flex: 1;
        min-width: 0;
        display: flex;
        flex-wrap: wrap;
        align-items: center;
        gap: 4px 8px;
      }
      .title {
        flex: 1 1 auto;
        min-width: 0;
      }
      .tags {
        display: flex;
        gap: 8px;
        margin-left: auto;
      }
      :host([status='current']) .title {
        font-weight: 700;
      }
      .done .mark {
        color: var(--rt-success);
      }
      .body {
        padding: 0 10px 10px;
      }
      /* A folded prediction's one line under its title (in full in its tooltip and when opened). */
      .summary {
        margin: -4px 10px 6px calc(10px + 1.4em + 8px);
        overflow: hidden;
        color: var(--rt-muted);
        font-size: 0.875em;
        white-space: nowrap;
        text-overflow: ellipsis;
      }
      .actions {
        display: flex;
        flex-wrap: wrap;
        gap: 8px;
        margin-top: 8px;
      }
      .checks {
        padding: 6px 8px;
        border-left: 4px solid var(--rt-accent);
        background: var(--rt-surface-2);
        border-radius: 6px;
      }
      .hint-box {
        display: block;
        margin-top: 8px;
      }
      /* As wide as the column: a figure is drawn to be read at 300 px and scales without loss (SVG). */
      .figure {
        display: block;
        width: 100%;
        height: auto;
        margin: 0 0 8px;
      }
    `,
  ];

  declare task: TaskView | undefined;
  declare locale: Locale;
  declare expanded: boolean;
  /** An optional task the learner opened to read. */
  declare private opened: boolean;

  constructor() {
    super();
    this.locale = 'en';
    this.expanded = false;
    this.opened = false;
  }

  /** The prediction stage last shown: a prediction that moves on (explained now) starts folded. */
  private stage: string | undefined;

  override willUpdate(): void {
    const stage = this.task?.prediction?.stage;
    if (stage !== this.stage) this.opened = false;
    this.stage = stage;
  }

  override updated(): void {
    // The status and the task's id are attributes so the styles (and browser tests) can see which task is current.
    if (!this.task) return;
    this.setAttribute('status', this.task.status);
    this.dataset.task = this.task.task.id;
  }

  override render() {
    const view = this.task;
    if (!view) return nothing;
    const finished = view.status === 'done' || view.status === 'shown' || view.status === 'skipped';
    const head = html`
      <span class="mark" aria-hidden="true">${MARKS[view.status]}</span>
      <span class="label">
        <span class="title">${plainLevelText(view.task.title, this.locale)}<span class="visually-hidden"> (${statusText(view)})</span></span>
        <span class="tags">
          ${requirementTag(view)}
          ${view.task.points > 0 ? html`<span class="tag muted" title=${msg('Points')}>${finished && view.prediction?.stage !== 'wait' ? msg(str`${view.points} pts`) : msg(str`${view.task.points} pts`)}</span>` : nothing}
        </span>
      </span>
    `;
    // Optional tasks and explained predictions open on request, so the current task keeps the learner's eye.
    const folded = this.expanded ? null : foldedPrediction(view, this.locale);
    const openable = (view.status === 'open' && !this.expanded) || folded !== null;
    const title = folded === null ? msg('Show or hide this optional task') : msg('Show or hide the answer and why');
    return html`
      ${
        openable
          ? html`<button class="head ${finished ? 'done' : ''}" aria-expanded=${String(this.opened)} title=${title} @click=${() => (this.opened = !this.opened)}>${head}</button>`
          : html`<div class="head ${finished ? 'done' : ''}">${head}</div>`
      }
      ${folded !== null && !this.opened ? html`<p class="summary" title=${folded}>${folded}</p>` : nothing}
      ${finished && view.task.goal.kind === 'challenge' ? html`<rt-challenge summary .goal=${view.task.goal} .stars=${view.stars ?? null} locale=${this.locale}></rt-challenge>` : nothing}
      ${finished && view.task.goal.kind === 'code' ? codeLabPanel(view.task.goal, this.locale, this) : nothing}
      ${this.expanded || (openable && this.opened) ? html`<div class="body">${this.body(view, finished)}</div>` : nothing}
    `;
  }

  private body(view: TaskView, finished: boolean): TemplateResult {
    const id = view.task.id;
    const send = (command: QuestCommand) => fire(this, QUEST_COMMAND, command);
    return html`
      ${checksLine(view, this.locale)}
      ${view.task.figure ? this.figure(view.task.figure) : nothing}
      <p>${levelText(view.task.text, this.locale)}</p>
      ${view.task.more ? explainMore(view.task.more, this.locale, () => send({ kind: 'explain', task: id })) : nothing}
      ${view.kind === 'quiz' ? html`<rt-quiz .task=${view} locale=${this.locale}></rt-quiz>` : nothing}
      ${view.task.goal.kind === 'challenge' ? html`<rt-challenge .goal=${view.task.goal} locale=${this.locale}></rt-challenge>` : nothing}
      ${view.task.goal.kind === 'code' && !finished ? codeLabPanel(view.task.goal, this.locale, this) : nothing}
      ${
        finished
          ? nothing
          : html`
            ${view.kind === 'info' ? html`<div class="actions"><button class="primary" @click=${() => send({ kind: 'next' })}>${msg('Next')}</button></div>` : nothing}
            ${view.kind === 'info' ? nothing : html`<rt-hint-box class="hint-box" .task=${view} locale=${this.locale}></rt-hint-box>`}
            ${view.required ? nothing : html`<div class="actions"><button class="link" title=${msg('Leave this optional task out (no points)')} @click=${() => send({ kind: 'skip', task: id })}>${msg('Skip')}</button></div>`}
          `
      }
    `;
  }

  private figure(figure: NonNullable<Task['figure']>) {
    const url = figureUrl(figure.src);
    return url ? html`<img class="figure" src=${url} alt=${plainLevelText(figure.alt, this.locale)} />` : nothing;
  }
}

/** Above a task that shows a prediction's result: what the learner predicted, to compare. */
function checksLine(view: TaskView, locale: Locale): TemplateResult | typeof nothing {
  const goal = view.checks && predictionOf(view.checks.quiz.goal);
  if (!view.checks || !goal) return nothing;
  const predicted = predictionText(goal, view.checks.prediction, locale, view.checks.order);
  return html`<p class="checks">${msg(str`You predicted: “${predicted}”. Watch what really happens.`)}</p>`;
}

/**
 * Whether the task counts for passing, as this learner's assignment has it: a task the
 * teacher made required says "required" (its level file calls it optional), one the
 * assignment leaves out says "optional"; a task the level itself requires needs no tag.
 */
function requirementTag(view: TaskView): TemplateResult | typeof nothing {
  if (!view.required) return html`<span class="tag muted">${msg('optional')}</span>`;
  return view.task.mandatory ? nothing : html`<span class="tag">${msg('required')}</span>`;
}

const MARKS: Record<TaskView['status'], string> = { current: '▶', open: '○', waiting: '·', done: '✓', shown: '✓', skipped: '–' };

function statusText(view: TaskView): string {
  switch (view.status) {
    case 'current':
      return msg('to do now');
    case 'open':
      return msg('optional, not done');
    case 'waiting':
      return msg('later');
    case 'done':
      return msg('done');
    case 'shown':
      return msg('shown to you');
    case 'skipped':
      return msg('skipped');
  }
}

customElements.define('rt-task-card', RtTaskCard);

declare global {
  interface HTMLElementTagNameMap {
    'rt-task-card': RtTaskCard;
  }
}
