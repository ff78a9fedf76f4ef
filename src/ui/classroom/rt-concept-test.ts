import { msg, str } from '@lit/localize';
import { css, html } from 'lit';
import type { ConceptTestSubmission } from '../../classroom/concept-test/concept-answers.ts';
import type { ConceptForm, ConceptItem } from '../../classroom/concept-test/concept-bank-schema.ts';
import { conceptBankNow, formItems, loadConceptBank } from '../../classroom/concept-test/concept-bank.ts';
import type { ConceptPhase } from '../../classroom/concept-test/concept-test-plan.ts';
import { currentLocale } from '../../i18n/locale.ts';
import { choiceOrder } from '../../quest/choice-order.ts';
import { localize, type Locale } from '../../quest/localized-text.ts';
import { classroomStyles } from './classroom-styles.ts';
import { focusQuestion, handInRow, questionCard, questionFormStyles } from './question-form.ts';
import { LocalizedElement } from '../controls/localized-element.ts';

/** What the page hands out: which test, and the answers. */
export interface ConceptTestHandIn {
  phase: ConceptPhase;
  submission: ConceptTestSubmission;
}

/**
 * @summary The concept test before the first level or after the last (issue 40), on a page of
 * its own over the game: every question of the form on one page that scrolls, each a group of
 * native radio buttons (arrow keys move between the choices, Tab to the next question, as in
 * the survey). The choices are shuffled per learner and item (choice-order.ts), so the right
 * one's place cannot be copied from a neighbour. It is a test: nothing says whether an answer
 * is right, before or after handing in. Every question needs an answer ("guess when you are
 * not sure"): an item left open would count as wrong without saying so.
 * @fires concept-test-submitted - detail: ConceptTestHandIn; save it (QuestSession.submitConceptTest).
 */
export class RtConceptTest extends LocalizedElement {
  static override properties = {
    phase: {},
    form: {},
    seed: {},
    locale: {},
    answers: { state: true },
    missing: { state: true },
  };

  static override styles = [
    classroomStyles,
    questionFormStyles,
    css`
      :host {
        position: fixed;
        inset: 0;
        z-index: 40;
        display: block;
        overflow-y: auto;
        background: var(--rt-bg);
        padding: 16px;
      }
      form {
        max-width: 760px;
        margin: 0 auto;
      }
      form:focus {
        outline: none;
      }
      h2 {
        margin: 0 0 8px;
      }
      label {
        display: flex;
        gap: 8px;
        align-items: center;
        min-height: var(--rt-target);
        cursor: pointer;
      }
    `,
  ];

  declare phase: ConceptPhase;
  declare form: ConceptForm;
  /** The playthrough's attempt id: the choices' order is the same after a reload. */
  declare seed: string;
  declare locale: Locale;
  declare answers: Record<string, string>;
  declare missing: string[];

  constructor() {
    super();
    this.phase = 'pre';
    this.form = 'A';
    this.seed = '';
    this.locale = currentLocale();
    this.answers = {};
    this.missing = [];
  }

  override connectedCallback(): void {
    super.connectedCallback();
    // The bank loads with the first element that shows it (concept-bank.ts).
    if (!conceptBankNow()) void loadConceptBank().then(() => this.requestUpdate());
  }

  private get items(): ConceptItem[] {
    const bank = conceptBankNow();
    return bank ? formItems(bank, this.form) : [];
  }

  /** The page covers the game: the focus comes onto it (read out by its heading), not left behind it. */
  protected override firstUpdated(): void {
    this.renderRoot.querySelector<HTMLElement>('form')?.focus();
  }

  private choose(item: string, choice: string): void {
    this.answers = { ...this.answers, [item]: choice };
    this.missing = this.missing.filter((id) => id !== item);
  }

  private async submit(event: Event): Promise<void> {
    event.preventDefault();
    const items = this.items;
    this.missing = items.filter((item) => !this.answers[item.id]).map((item) => item.id);
    if (this.missing.length > 0) {
      await focusQuestion(this, this.missing[0]!);
      return;
    }
    const answers = Object.fromEntries(items.map((item) => [item.id, this.answers[item.id]!]));
    const detail: ConceptTestHandIn = { phase: this.phase, submission: { form: this.form, submittedAt: new Date().toISOString(), answers } };
    this.dispatchEvent(new CustomEvent<ConceptTestHandIn>('concept-test-submitted', { detail, bubbles: true, composed: true }));
  }

  override render() {
    const items = this.items;
    const before = this.phase === 'pre';
    return html`<form tabindex="-1" aria-labelledby="heading" novalidate @submit=${this.submit}>
      <h2 id="heading">${before ? msg('Before you start: what do you think?') : msg('You are done: the questions once more')}</h2>
      <p>
        ${
          before
            ? msg(
                str`${items.length} questions about light and rays. Choose what you think now; guess when you are not sure. You will not see whether your answers are right. After the last level you get questions like these again, so that your teacher can see what you learned.`,
              )
            : msg(
                str`${items.length} questions like the ones at the start, about the same ideas. Choose what you think now. You will not see whether your answers are right.`,
              )
        }
      </p>
      ${items.map((item, index) => this.renderItem(item, index + 1))}
      ${handInRow(this.missing.length, (count) => (count === 1 ? msg('1 question has no answer yet.') : msg(str`${count} questions have no answer yet.`)))}
    </form>`;
  }

  private renderItem(item: ConceptItem, number: number) {
    const missing = this.missing.includes(item.id);
    const order = choiceOrder(item.choices.length, `${this.seed}/${item.id}`);
    return questionCard({
      id: item.id,
      legend: html`${number}. ${localize(item.question, this.locale)}`,
      input: html`${order.map((position) => {
        const choice = item.choices[position]!;
        return html`<label>
          <input type="radio" name=${item.id} .checked=${this.answers[item.id] === choice.id} @change=${() => this.choose(item.id, choice.id)} />
          ${localize(choice.text, this.locale)}
        </label>`;
      })}`,
      problem: missing ? msg('Please choose an answer (a guess is fine).') : '',
    });
  }
}

customElements.define('rt-concept-test', RtConceptTest);

declare global {
  interface HTMLElementTagNameMap {
    'rt-concept-test': RtConceptTest;
  }
}
