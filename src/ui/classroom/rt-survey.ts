import { msg, str } from '@lit/localize';
import { css, html, nothing } from 'lit';
import { LocalizedElement } from '../controls/localized-element.ts';
import { checkAnswers, cleanAnswers, type AnswerProblem, type SurveyAnswers, type SurveySubmission } from '../../classroom/survey-answers.ts';
import type { Survey, SurveyQuestion } from '../../classroom/survey-schema.ts';
import { surveyById } from '../../classroom/surveys.ts';
import { surveyAsked } from '../../classroom/survey-for-levels.ts';
import type { Assignment } from '../../classroom/assignment.ts';
import { currentLocale } from '../../i18n/locale.ts';
import { localize, type Locale } from '../../quest/localized-text.ts';
import { classroomStyles } from './classroom-styles.ts';
import { focusQuestion, handInRow, questionCard, questionFormStyles } from './question-form.ts';

/**
 * @summary The closing questionnaire: one question after another on a page that scrolls,
 * every control a native radio, field or text area (keyboard and screen readers work as
 * everywhere). "Hand in" checks the answers; each problem is said next to its question and
 * the first one gets the focus.
 * @fires survey-submitted - detail: SurveySubmission (the survey's id, the time, the answers);
 * save it next to the progress (survey-keeper.ts, survey-store.ts), and pass it to the exports.
 */
export class RtSurvey extends LocalizedElement {
  static override properties = {
    surveyId: { attribute: 'survey-id' },
    locale: {},
    levels: { attribute: false },
    choice: { attribute: false },
    questions: { attribute: false },
    answers: { state: true },
    problems: { state: true },
    submitted: { state: true },
  };

  static override styles = [
    classroomStyles,
    questionFormStyles,
    css`
      :host {
        display: block;
        /* Size containment gives the host no width of its own: it takes its column's, or it collapses in a column sized by content. */
        width: 100%;
        box-sizing: border-box;
        max-width: 760px;
        margin: 0 auto;
        /* The scales fold by the survey's own width (its page's column), not the window's. */
        container-type: inline-size;
        padding: calc(var(--rt-space) * 2);
      }
      h2 {
        margin: 0 0 var(--rt-space);
      }
      .optional {
        font-weight: normal;
        color: var(--rt-muted);
      }
      .options {
        display: flex;
        flex-wrap: wrap;
        gap: 6px 18px;
      }
      .options label {
        display: inline-flex;
        gap: 6px;
        align-items: center;
        min-height: var(--rt-target);
        cursor: pointer;
      }
      .scale {
        display: grid;
        grid-template-columns: auto 1fr auto;
        gap: 8px;
        align-items: center;
      }
      .scale .options {
        justify-content: space-between;
        gap: 4px;
      }
      .scale .options label {
        flex-direction: column;
        gap: 2px;
        min-width: var(--rt-target);
      }
      .end {
        font-size: 0.9em;
        color: var(--rt-muted);
        max-width: 8em;
      }
      textarea {
        width: 100%;
        min-height: 4.5em;
        resize: vertical;
      }
      /* A narrow survey (a phone) puts the ends' labels above and below the scale, and its
         steps share one row: 1 to 10 in a 300 px row leaves each step's target 29 px wide,
         above WCAG 2.2's 24 px minimum, instead of breaking the scale over two rows. */
      @container (max-width: 520px) {
        .scale {
          grid-template-columns: 1fr;
        }
        .scale .options {
          flex-wrap: nowrap;
          gap: 0;
        }
        .scale .options label {
          flex: 1;
          min-width: 0;
        }
      }
    `,
  ];

  declare surveyId: string;
  declare locale: Locale;
  /** The assignment's levels: questions on ideas none of them teaches are left out; null (a preview) asks them all. */
  declare levels: readonly string[] | null;
  /** The teacher's own choice of questions (Assignment.surveyQuestions), over the levels' default. */
  declare choice: Assignment['surveyQuestions'];
  /** Exactly these questions, by id (the teacher's preview of their choice, survey-preview-link.ts); null: by the levels and the choice. */
  declare questions: readonly string[] | null;
  declare answers: SurveyAnswers;
  declare problems: Record<string, AnswerProblem>;
  declare submitted: boolean;

  constructor() {
    super();
    this.surveyId = 'default';
    // The page's language, unless the assignment names its own (a teacher's preview names none).
    this.locale = currentLocale();
    this.levels = null;
    this.questions = null;
    this.answers = {};
    this.problems = {};
    this.submitted = false;
  }

  private get survey(): Survey | undefined {
    const survey = surveyById(this.surveyId);
    const only = this.questions;
    if (survey && only) return surveyAsked(survey, null, Object.fromEntries(survey.questions.map((question) => [question.id, only.includes(question.id)])));
    return survey && surveyAsked(survey, this.levels, this.choice);
  }

  private text(text: Parameters<typeof localize>[0]): string {
    return localize(text, this.locale);
  }

  private answer(id: string, value: string | number | undefined): void {
    const answers = { ...this.answers };
    if (value === undefined) delete answers[id];
    else answers[id] = value;
    this.answers = answers;
    // A fixed answer loses its message at once; new messages wait for the next "Hand in".
    if (this.problems[id]) {
      const { [id]: _fixed, ...rest } = this.problems;
      this.problems = rest;
    }
  }

  private async submit(event: Event): Promise<void> {
    event.preventDefault();
    const survey = this.survey;
    if (!survey) return;
    this.problems = checkAnswers(survey, this.answers);
    const first = survey.questions.find((question) => this.problems[question.id]);
    if (first) {
      await focusQuestion(this, first.id);
      return;
    }
    const submission: SurveySubmission = { survey: survey.id, submittedAt: new Date().toISOString(), answers: cleanAnswers(survey, this.answers) };
    this.submitted = true;
    this.dispatchEvent(new CustomEvent<SurveySubmission>('survey-submitted', { detail: submission, bubbles: true, composed: true }));
  }

  override render() {
    const survey = this.survey;
    if (!survey) return html`<p class="problem" role="alert">${msg(str`The survey "${this.surveyId}" is not part of this version of the game.`)}</p>`;
    if (this.submitted) return html`<h2>${this.text(survey.title)}</h2><p role="status">${msg('Thank you for your answers.')}</p>`;
    return html`
      <form @submit=${this.submit} novalidate>
        <h2>${this.text(survey.title)}</h2>
        ${survey.intro ? html`<p>${this.text(survey.intro)}</p>` : nothing}
        ${survey.questions.map((question, index) => this.renderQuestion(question, index + 1))}
        ${handInRow(Object.keys(this.problems).length, (count) => (count === 1 ? msg('1 answer still needs attention.') : msg(str`${count} answers still need attention.`)))}
      </form>
    `;
  }

  private renderQuestion(question: SurveyQuestion, number: number) {
    const problem = this.problems[question.id];
    return questionCard({
      id: question.id,
      legend: html`${number}. ${this.text(question.text)} ${question.required ? nothing : html`<span class="optional">${msg('(optional)')}</span>`}`,
      input: this.renderInput(question),
      problem: problem ? this.describe(problem) : '',
    });
  }

  private renderInput(question: SurveyQuestion) {
    const value = this.answers[question.id];
    switch (question.type) {
      case 'choice':
        return html`<div class="options">
          ${question.options.map(
            (option) => html`<label>
              <input type="radio" name=${question.id} .checked=${value === option.id} @change=${() => this.answer(question.id, option.id)} />
              ${this.text(option.text)}
            </label>`,
          )}
        </div>`;
      case 'scale': {
        const steps = Array.from({ length: question.max - question.min + 1 }, (_, i) => question.min + i);
        const minLabel = this.text(question.minLabel);
        const maxLabel = this.text(question.maxLabel);
        return html`<div class="scale">
          <span class="end" aria-hidden="true">${question.min} = ${minLabel}</span>
          <div class="options">
            ${steps.map(
              (step) => html`<label title=${step === question.min ? minLabel : step === question.max ? maxLabel : String(step)}>
                <input
                  type="radio"
                  name=${question.id}
                  .checked=${value === step}
                  aria-label=${step === question.min ? `${step}, ${minLabel}` : step === question.max ? `${step}, ${maxLabel}` : String(step)}
                  @change=${() => this.answer(question.id, step)}
                />
                <span aria-hidden="true">${step}</span>
              </label>`,
            )}
          </div>
          <span class="end" aria-hidden="true">${question.max} = ${maxLabel}</span>
        </div>`;
      }
      case 'number':
        return html`<input
          type="text"
          inputmode=${question.integer ? 'numeric' : 'decimal'}
          aria-label=${this.text(question.text)}
          .value=${value === undefined ? '' : String(value)}
          @change=${(event: Event) => this.answer(question.id, readNumber((event.target as HTMLInputElement).value))}
        />`;
      case 'text':
        return html`<textarea
          aria-label=${this.text(question.text)}
          maxlength=${question.maxLength}
          .value=${typeof value === 'string' ? value : ''}
          @input=${(event: Event) => this.answer(question.id, (event.target as HTMLTextAreaElement).value)}
        ></textarea>`;
    }
  }

  private describe(problem: AnswerProblem): string {
    switch (problem.kind) {
      case 'required':
        return msg('Please answer this question.');
      case 'not-a-number':
        return msg('Please type a number, like 25.');
      case 'not-whole':
        return msg('Please type a whole number.');
      case 'out-of-range':
        return problem.min !== undefined && problem.max !== undefined
          ? msg(str`Please type a number from ${problem.min} to ${problem.max}.`)
          : problem.min !== undefined
            ? msg(str`Please type a number of at least ${problem.min}.`)
            : msg(str`Please type a number of at most ${problem.max}.`);
      case 'too-long':
        return msg(str`Please keep it under ${problem.max} characters.`);
      case 'unknown-option':
        return msg('Please pick one of the options.');
    }
  }
}

/** A typed number ("25", "2,5" with a Dutch comma); text that is no number stays text, so the check can say so. */
function readNumber(text: string): string | number | undefined {
  const trimmed = text.trim();
  if (trimmed === '') return undefined;
  const value = Number(trimmed.replace(',', '.'));
  return Number.isFinite(value) ? value : trimmed;
}

customElements.define('rt-survey', RtSurvey);

declare global {
  interface HTMLElementTagNameMap {
    'rt-survey': RtSurvey;
  }
}
