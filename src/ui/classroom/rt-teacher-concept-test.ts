import { msg, str } from '@lit/localize';
import { css, html } from 'lit';
import { conceptBankNow, formItems, loadConceptBank } from '../../classroom/concept-test/concept-bank.ts';
import { CONCEPT_TEST_ORDERS, type ConceptTestOrder } from '../../classroom/concept-test/concept-test-plan.ts';
import { classroomStyles } from './classroom-styles.ts';
import { LocalizedElement } from '../controls/localized-element.ts';

/**
 * @summary The teacher page's section for the concept test (issue 40, "learning measured"):
 * off (the default), form A before the first level and form B after the last, or
 * counterbalanced (half of the learners, by their attempt id, take B first). Without an item
 * bank in this version of the app there is nothing to choose, and it says so.
 * @fires concept-test-change - detail: ConceptTestOrder, or undefined for none.
 */
export class RtTeacherConceptTest extends LocalizedElement {
  static override properties = { value: { attribute: false } };

  static override styles = [
    classroomStyles,
    css`
      /* A card like the page's other sections (classroom-styles.ts pageStyles). */
      :host {
        display: block;
        margin-bottom: calc(var(--rt-space) * 2);
        background: var(--rt-surface);
        border: 1px solid var(--rt-border);
        border-radius: var(--rt-radius);
        padding: 12px 16px;
      }
      h2 {
        font-size: 1.05rem;
        margin: 0 0 var(--rt-space);
      }
      fieldset {
        border: 0;
        margin: 0;
        padding: 0;
      }
      legend {
        font-size: 0.9em;
        color: var(--rt-muted);
        padding: 0;
      }
      label {
        display: flex;
        gap: 6px;
        align-items: center;
        min-height: 28px;
        cursor: pointer;
      }
      p {
        margin: 4px 0 0;
        font-size: 0.9em;
        color: var(--rt-muted);
      }
    `,
  ];

  declare value: ConceptTestOrder | undefined;

  constructor() {
    super();
    this.value = undefined;
  }

  override connectedCallback(): void {
    super.connectedCallback();
    // The bank loads with the first element that shows it (concept-bank.ts).
    if (!conceptBankNow()) void loadConceptBank().then(() => this.requestUpdate());
  }

  private pick(value: ConceptTestOrder | undefined): void {
    this.value = value;
    this.dispatchEvent(new CustomEvent('concept-test-change', { detail: value, bubbles: true, composed: true }));
  }

  override render() {
    const labels: Record<ConceptTestOrder, string> = {
      'a-then-b': msg('Form A before the first level, form B after the last'),
      counterbalanced: msg('Counterbalanced: about half of the students, chosen at random, take form B first'),
    };
    const bank = conceptBankNow();
    const size = bank ? formItems(bank, 'A').length : 0;
    return html`<h2>${msg('Concept test: learning measured (optional)')}</h2>
      ${
        bank
          ? html`<fieldset>
              <legend>${msg('A short multiple-choice test before and after the levels')}</legend>
              <label><input type="radio" name="concept-test" .checked=${!this.value} @change=${() => this.pick(undefined)} />${msg('None')}</label>
              ${CONCEPT_TEST_ORDERS.map(
                (order) =>
                  html`<label><input type="radio" name="concept-test" .checked=${this.value === order} @change=${() => this.pick(order)} />${labels[order]}</label>`,
              )}
            </fieldset>
            <p>
              ${msg(
                str`Forms A and B each have ${size} questions on the same ideas. The dashboard shows the scores before and after and the normalized gain per idea.`,
              )}
            </p>`
          : html`<p>${msg('This version of the app has no concept test.')}</p>`
      }`;
  }
}

customElements.define('rt-teacher-concept-test', RtTeacherConceptTest);

declare global {
  interface HTMLElementTagNameMap {
    'rt-teacher-concept-test': RtTeacherConceptTest;
  }
}
