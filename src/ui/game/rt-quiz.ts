import { msg, str } from '@lit/localize';
import { css, html, LitElement, nothing, type TemplateResult } from 'lit';
import type { Locale } from '../../quest/localized-text.ts';
import type { TaskView } from '../../quest/quest-engine.ts';
import { plainLevelText } from '../../quest/text-markup.ts';
import { fire, gameStyles } from './game-styles.ts';
import { levelText } from './level-text.ts';
import { QUEST_COMMAND, type QuestCommand } from './quest-command.ts';

/**
 * @summary A predict-then-check question: the choices as radio buttons, "Check", then
 * whether the prediction was right, the answer and why. After "Show me" (the answer
 * revealed) it shows the answer and the explanation.
 *
 * @fires quest-command - `answer` with the chosen position.
 */
export class RtQuiz extends LitElement {
  static override properties = { task: { attribute: false }, locale: {}, picked: { state: true } };
  static override styles = [
    gameStyles,
    css`
      fieldset {
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
        align-items: center;
        gap: 8px;
        min-height: var(--rt-target);
        cursor: pointer;
      }
      input[type='radio'] {
        width: 18px;
        height: 18px;
        margin: 0;
        accent-color: var(--rt-accent);
      }
      .right {
        color: var(--rt-success);
      }
      .wrong {
        color: var(--rt-danger);
      }
      .feedback {
        padding: 8px;
        border-left: 4px solid currentColor;
        background: var(--rt-surface-2);
        border-radius: 6px;
      }
      .feedback p:last-child {
        margin: 0;
        color: var(--rt-text);
      }
    `,
  ];

  declare task: TaskView | undefined;
  declare locale: Locale;
  declare picked: number | null;

  constructor() {
    super();
    this.locale = 'en';
    this.picked = null;
  }

  override render() {
    const view = this.task;
    if (!view || !('quiz' in view.task.goal)) return nothing;
    const quiz = view.task.goal.quiz;
    const answered = view.status === 'done' || view.status === 'shown';
    const name = `quiz-${view.task.id}`;
    return html`
      <fieldset ?disabled=${answered}>
        <legend>${levelText(quiz.question, this.locale)}</legend>
        ${quiz.choices.map(
          (choice, index) => html`<label>
            <input type="radio" name=${name} .checked=${this.picked === index} @change=${() => (this.picked = index)} />
            ${levelText(choice, this.locale)} ${answered && index === quiz.answer ? html`<span class="tag right">✓ ${msg('answer')}</span>` : nothing}
            ${answered && index === this.picked && index !== quiz.answer ? html`<span class="tag wrong">✗ ${msg('your answer')}</span>` : nothing}
          </label>`,
        )}
      </fieldset>
      ${answered
        ? this.feedback(view, plainLevelText(quiz.choices[quiz.answer] ?? '', this.locale), quiz.explanation ? levelText(quiz.explanation, this.locale) : null)
        : html`<button class="primary" ?disabled=${this.picked === null} @click=${this.check} title=${msg('Check your prediction')}>${msg('Check')}</button>`}
    `;
  }

  /** The verdict names the answer inside a sentence of the app's, so as plain text; the explanation keeps its bold names. */
  private feedback(view: TaskView, answer: string, explanation: TemplateResult | null) {
    const verdict =
      view.status === 'shown'
        ? html`<p><strong>${msg(str`The answer: ${answer}`)}</strong></p>`
        : view.correct
          ? html`<p class="right"><strong>✓ ${msg('Right!')}</strong></p>`
          : html`<p class="wrong"><strong>✗ ${msg(str`Not quite: the answer is ${answer}.`)}</strong></p>`;
    return html`<div class="feedback ${view.status === 'done' && !view.correct ? 'wrong' : 'right'}" role="status">${verdict}${explanation ? html`<p>${explanation}</p>` : nothing}</div>`;
  }

  private check(): void {
    const view = this.task;
    if (!view || this.picked === null) return;
    const command: QuestCommand = { kind: 'answer', task: view.task.id, choice: this.picked };
    fire(this, QUEST_COMMAND, command);
  }
}

customElements.define('rt-quiz', RtQuiz);

declare global {
  interface HTMLElementTagNameMap {
    'rt-quiz': RtQuiz;
  }
}
