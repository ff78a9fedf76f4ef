import { msg, str } from '@lit/localize';
import { ContextConsumer } from '@lit/context';
import { css, html, nothing, type TemplateResult } from 'lit';
import { LocalizedElement } from '../controls/localized-element.ts';
import type { Prediction } from '../../quest/goal-check.ts';
import { explanationOf, predictionOf, predictionParts, type PictureGoal, type PredictionGoal, type QuizGoal } from '../../quest/goal.ts';
import type { Locale } from '../../quest/localized-text.ts';
import type { TaskView } from '../../quest/level-view.ts';
import { plainLevelText } from '../../quest/text-markup.ts';
import { parseTypedNumber } from '../controls/number-input.ts';
import { fire, gameStyles } from './game-styles.ts';
import { levelText } from './level-text.ts';
import { QUEST_COMMAND, type QuestCommand } from './quest-command.ts';
import { answerText, choiceLabel, predictionText } from './prediction-text.ts';
import { quizPicturesContext } from './quiz-pictures.ts';

/**
 * @summary A prediction, as predict → observe → explain: the learner picks a choice (in an
 * order of their own, so the key's place tells nothing) or types a number and locks it in;
 * nothing says whether it was right until the task that shows the result is done. Then a
 * learner who expected something else is asked what they see now, and only after that are
 * the answer and the explanation shown, with Continue. After "Show me" it shows the answer.
 * A picture prediction's choices are small renders (drawn by the lab's quizPicturesContext),
 * lettered A, B, … in the order shown.
 *
 * @fires quest-command - `predict`, `reflect` (with the choice or number) and `continue`.
 */
export class RtQuiz extends LocalizedElement {
  static override properties = { task: { attribute: false }, locale: {}, picked: { state: true }, typed: { state: true }, problem: { state: true } };
  static override styles = [
    gameStyles,
    css`
      /* A fieldset is at least as wide as its widest word by default: a long Dutch choice
         with its tags pushed the quiz out of the task column. */
      fieldset {
        min-width: 0;
        margin: 0 0 8px;
        padding: 0;
        border: 0;
      }
      legend {
        margin-bottom: 6px;
        font-weight: 600;
      }
      label {
        display: flex;
        flex-wrap: wrap;
        align-items: center;
        gap: 4px 8px;
        min-height: var(--rt-target);
        cursor: pointer;
      }
      .choice {
        flex: 1 1 8em;
        min-width: 0;
      }
      input[type='radio'] {
        flex: none;
        width: 18px;
        height: 18px;
        margin: 0;
        accent-color: var(--rt-accent);
      }
      .number {
        display: flex;
        align-items: center;
        gap: 6px;
      }
      .number input {
        width: 8em;
        min-height: var(--rt-target);
      }
      .right {
        color: var(--rt-success);
      }
      .wrong {
        color: var(--rt-danger);
      }
      .feedback {
        padding: 8px;
        border-left: 4px solid var(--rt-accent);
        background: var(--rt-surface-2);
        border-radius: 6px;
      }
      .feedback p:last-child {
        margin-bottom: 0;
      }
      .problem {
        color: var(--rt-danger);
      }
      .pictures {
        display: grid;
        grid-template-columns: repeat(2, minmax(0, 1fr));
        gap: 6px;
      }
      .pictures label {
        flex-direction: column;
        align-items: stretch;
        gap: 4px;
        padding: 4px;
        border: 1px solid var(--rt-border);
        border-radius: 6px;
      }
      .pictures label:has(input:checked) {
        border: 2px solid var(--rt-accent);
      }
      .pictures .letter {
        display: flex;
        align-items: center;
        gap: 6px;
      }
      .pictures .frame {
        position: relative;
      }
      .pictures .state {
        position: absolute;
        inset: 0;
        display: grid;
        place-items: center;
        text-align: center;
        font-size: 0.8rem;
        color: var(--rt-muted);
      }
      .pictures canvas {
        display: block;
        width: 100%;
        height: auto;
        background: var(--rt-surface-2);
        image-rendering: pixelated;
      }
    `,
  ];

  declare task: TaskView | undefined;
  declare locale: Locale;
  /** The choice (file position) the learner has picked and not yet sent. */
  declare picked: number | null;
  /** The number the learner is typing. */
  declare typed: string;
  /** Why the typed text is not a number. */
  declare problem: string;
  /** The stage `picked`/`typed` belong to: they are cleared when it moves on. */
  private pickedFor = '';
  private readonly pictures = new ContextConsumer(this, { context: quizPicturesContext, subscribe: true });
  /** The pictures painted into this element's canvases, by scene (null: it could not be made), or still being drawn: a re-render keeps them. */
  private readonly painted = new Map<object, ImageData | null | 'drawing'>();

  constructor() {
    super();
    this.locale = 'en';
    this.picked = null;
    this.typed = '';
    this.problem = '';
  }

  override render() {
    const view = this.task;
    const goal = view && predictionOf(view.task.goal);
    const stage = view?.prediction?.stage;
    if (!view || !goal || !stage) return nothing;
    const key = `${view.task.id}/${stage}`;
    if (key !== this.pickedFor) [this.pickedFor, this.picked, this.typed, this.problem] = [key, null, '', ''];
    if (view.status === 'shown') return this.shown(goal);
    switch (stage) {
      case 'ask':
        return this.asking(view, goal, 'predict', levelText(questionOf(goal), this.locale), msg('Lock in my prediction'));
      case 'wait':
        return html`${this.asked(view, goal)}<div class="feedback" role="status">
            <p><strong>${msg(str`Your prediction: “${this.said(goal, view.prediction?.prediction)}”.`)}</strong></p>
            <p>${msg('Now find out: do the next task and look closely. The answer comes after that.')}</p>
          </div>`;
      case 'reflect':
        return html`<div class="feedback" role="status">
            <p><strong>${msg(str`You expected: “${this.said(goal, view.prediction?.prediction)}”.`)}</strong></p>
          </div>
          ${this.asking(view, goal, 'reflect', msg('You have seen the result now. What do you see?'), msg('This is what I see'))}`;
      case 'explain':
      case 'explained':
        return this.explained(view, goal, stage === 'explain');
    }
  }

  /** The question with its choices (or number box) to answer, and the button that sends it. */
  private asking(view: TaskView, goal: PredictionGoal, kind: 'predict' | 'reflect', legend: TemplateResult | string, button: string): TemplateResult {
    const send = () => {
      const prediction = this.chosen(goal);
      if (!prediction) return;
      const command: QuestCommand = { kind, task: view.task.id, prediction };
      fire(this, QUEST_COMMAND, command);
    };
    const ready = goal.kind === 'estimate' ? this.typed.trim() !== '' : this.picked !== null;
    return html`<fieldset>
        <legend>${legend}</legend>
        ${goal.kind === 'estimate' ? this.numberBox(goal, send) : this.choices(view, goal, true)}
      </fieldset>
      ${this.problem ? html`<p class="problem" role="alert">${this.problem}</p>` : nothing}
      <button class="primary" ?disabled=${!ready} @click=${send}>${button}</button>`;
  }

  /** The question as asked, with the learner's prediction marked, once it is locked in. */
  private asked(view: TaskView, goal: PredictionGoal): TemplateResult {
    return html`<fieldset disabled>
      <legend>${levelText(questionOf(goal), this.locale)}</legend>
      ${goal.kind === 'estimate' ? nothing : this.choices(view, goal, false)}
    </fieldset>`;
  }

  /** The choices (words or pictures) in this learner's order; `open` while they may pick one. */
  private choices(view: TaskView, goal: QuizGoal | PictureGoal, open: boolean): TemplateResult {
    const { choices, answer } = predictionParts(goal);
    const order = view.prediction?.order.length === choices ? view.prediction.order : Array.from({ length: choices }, (_, index) => index);
    const mine = view.prediction?.prediction;
    const reveal = view.prediction?.stage === 'explain' || view.prediction?.stage === 'explained';
    const pictures = view.prediction?.pictures;
    const items = order.map((index) => {
      const text = choiceLabel(goal, index, order, this.locale);
      // A quiz's choice keeps its bold names; the picture's label and the aria text are plain.
      const shown = goal.kind === 'quiz' ? levelText(goal.quiz.choices[index], this.locale) : text;
      const tags = html`${!open && mine && 'choice' in mine && mine.choice === index ? html`<span class="tag">${msg('your prediction')}</span>` : nothing}
      ${reveal && index === answer ? html`<span class="tag right">✓ ${msg('answer')}</span>` : nothing}`;
      const radio = html`<input type="radio" name=${`quiz-${view.task.id}`} .checked=${open ? this.picked === index : mine !== undefined && 'choice' in mine && mine.choice === index} @change=${() => (this.picked = index)} />`;
      if (!pictures) return html`<label>${radio}<span class="choice">${shown}</span>${tags}</label>`;
      const [width, height] = pictures[index].settings.imageSize;
      const painted = this.painted.get(pictures[index]);
      // Renders take a few seconds on a slow machine: an empty frame would look broken.
      const state = painted === undefined || painted === 'drawing' ? msg('Drawing…') : painted === null ? msg('Could not be drawn') : '';
      // The render is for the eye (no words could stand for it): the radio's name is its letter.
      return html`<label>
        <span class="frame"
          ><canvas data-picture=${index} width=${width} height=${height} aria-hidden="true"></canvas>${
            state ? html`<span class="state" aria-hidden="true">${state}</span>` : nothing
          }</span
        >
        <span class="letter">${radio} ${text} ${tags}</span>
      </label>`;
    });
    return pictures ? html`<div class="pictures">${items}</div>` : html`${items}`;
  }

  protected override updated(): void {
    const pictures = this.task?.prediction?.pictures;
    const drawer = this.pictures.value;
    if (!pictures || !drawer) return;
    for (const canvas of this.renderRoot.querySelectorAll<HTMLCanvasElement>('canvas[data-picture]')) {
      const scene = pictures[Number(canvas.dataset.picture)];
      const done = this.painted.get(scene);
      if (done !== undefined) {
        if (done instanceof ImageData) canvas.getContext('2d')?.putImageData(done, 0, 0);
        continue;
      }
      void drawer.draw(scene).then((image) => {
        this.painted.set(scene, image);
        this.requestUpdate();
      });
      this.painted.set(scene, 'drawing');
    }
  }

  private numberBox(goal: PredictionGoal, send: () => void): TemplateResult {
    const unit = goal.kind === 'estimate' && goal.estimate.unit ? plainLevelText(goal.estimate.unit, this.locale) : '';
    return html`<label class="number"
      ><input
        type="text"
        inputmode="decimal"
        autocomplete="off"
        aria-label=${msg('Your number')}
        .value=${this.typed}
        @input=${(event: Event) => {
          this.typed = (event.target as HTMLInputElement).value;
          this.problem = '';
        }}
        @keydown=${(event: KeyboardEvent) => event.key === 'Enter' && send()}
      />${unit}</label
    >`;
  }

  /** The answer and why, after the observation; `current` adds Continue. */
  private explained(view: TaskView, goal: PredictionGoal, current: boolean): TemplateResult {
    const mine = view.prediction?.prediction;
    const seen = view.prediction?.reflection;
    const answer = answerText(goal, this.locale, this.task?.prediction?.order ?? []);
    const explanation = explanationOf(goal);
    const verdict = view.correct
      ? html`<p class="right"><strong>✓ ${msg(str`You expected “${this.said(goal, mine)}”, and so it is.`)}</strong></p>`
      : html`<p><strong>${msg(str`You expected “${this.said(goal, mine)}”; the answer is “${answer}”.`)}</strong></p>
          ${seen ? html`<p>${msg(str`You saw: “${this.said(goal, seen)}”.`)}</p>` : nothing}`;
    return html`${this.asked(view, goal)}
      <div class="feedback" role="status">${verdict}${explanation ? html`<p>${levelText(explanation, this.locale)}</p>` : nothing}</div>
      ${current ? html`<button class="primary" @click=${() => fire(this, QUEST_COMMAND, { kind: 'continue', task: view.task.id } satisfies QuestCommand)}>${msg('Continue')}</button>` : nothing}`;
  }

  /** After "Show me": the answer and the explanation. */
  private shown(goal: PredictionGoal): TemplateResult {
    const explanation = explanationOf(goal);
    return html`<div class="feedback" role="status">
      <p><strong>${msg(str`The answer: “${answerText(goal, this.locale, this.task?.prediction?.order ?? [])}”`)}</strong></p>
      ${explanation ? html`<p>${levelText(explanation, this.locale)}</p>` : nothing}
    </div>`;
  }

  private said(goal: PredictionGoal, prediction: Prediction | undefined): string {
    return prediction ? predictionText(goal, prediction, this.locale, this.task?.prediction?.order ?? []) : '…';
  }

  /** The picked choice or the typed number; a typed text that is no number says why. */
  private chosen(goal: PredictionGoal): Prediction | undefined {
    if (goal.kind !== 'estimate') return this.picked === null ? undefined : { choice: this.picked };
    const unit = goal.estimate.unit ? plainLevelText(goal.estimate.unit, this.locale) : '';
    const read = parseTypedNumber(this.typed, { min: -Number.MAX_VALUE, max: Number.MAX_VALUE }, unit);
    if (read.kind === 'invalid') {
      this.problem = msg('Type a number, for example 0.5 or 12.');
      return undefined;
    }
    return { value: read.value };
  }
}

function questionOf(goal: PredictionGoal) {
  return predictionParts(goal).question;
}

customElements.define('rt-quiz', RtQuiz);

declare global {
  interface HTMLElementTagNameMap {
    'rt-quiz': RtQuiz;
  }
}
