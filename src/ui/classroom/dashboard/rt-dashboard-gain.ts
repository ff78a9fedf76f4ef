import { msg, str } from '@lit/localize';
import { css, html, nothing } from 'lit';
import type { ConceptBank } from '../../../classroom/concept-test/concept-bank-schema.ts';
import { conceptBankNow, loadConceptBank } from '../../../classroom/concept-test/concept-bank.ts';
import { conceptGains, type ClassGain, type GainLearner, type GainRow } from '../../../classroom/concept-test/concept-gain.ts';
import { studentsCounted } from '../../../i18n/counted.ts';
import { localize, type Locale } from '../../../quest/localized-text.ts';
import { tableStyles } from './rt-dashboard-chart-styles.ts';
import { formatPercent } from './rt-dashboard-format.ts';
import { LocalizedElement } from '../../controls/localized-element.ts';

/**
 * @summary The concept test on the dashboard: per class a table of the ideas, each with the
 * number of learners who took both tests (n), the class's average score before and after and
 * Hake's normalized gain ⟨g⟩ of those averages (concept-gain.ts). Shown only when a learner
 * shown took a concept test.
 */
export class RtDashboardGain extends LocalizedElement {
  static override properties = { learners: { attribute: false }, locale: {} };

  static override styles = [
    tableStyles,
    css`
      :host {
        display: block;
      }
      h3 {
        margin: var(--rt-space) 0 4px;
        font-size: 1rem;
      }
      td {
        text-align: right;
      }
      th[scope='row'] {
        text-align: left;
        font-weight: normal;
      }
      tr.whole th,
      tr.whole td {
        font-weight: 600;
      }
      p {
        max-width: 60em;
        font-size: 0.9rem;
      }
    `,
  ];

  declare learners: readonly GainLearner[];
  declare locale: Locale;

  constructor() {
    super();
    this.learners = [];
    this.locale = 'en';
  }

  override connectedCallback(): void {
    super.connectedCallback();
    // The bank loads with the first element that shows it (concept-bank.ts).
    if (!conceptBankNow()) void loadConceptBank().then(() => this.requestUpdate());
  }

  override render() {
    const bank = conceptBankNow();
    if (!bank) return nothing;
    const classes = conceptGains(this.learners, bank);
    if (classes.length === 0) return nothing;
    return html`<p>
        ${msg(
          "Scores are the share of questions answered right, averaged over the students who took both tests (n). ⟨g⟩ is the normalized gain of those class averages, (after − before) / (100 % − before) (Hake 1998): the part of what was left to learn that was learned. It is not the average of each student's gain.",
        )}
      </p>
      ${classes.map((group) => this.renderClass(group, bank))}`;
  }

  private renderClass(group: ClassGain, bank: ConceptBank) {
    const name = group.classCode === '' ? msg('Students without a class code') : msg(str`Class ${group.classCode}`);
    const concept = (row: GainRow) =>
      row.concept === null ? msg('Whole test') : localize(bank.concepts.find((candidate) => candidate.id === row.concept)?.name ?? row.concept, this.locale);
    const number = new Intl.NumberFormat(this.locale, { minimumFractionDigits: 2, maximumFractionDigits: 2 });
    return html`<h3>${name}</h3>
      <table data-class=${group.classCode}>
        <caption>
          ${msg(str`Concept test of ${name}: scores before and after, and normalized gain per idea`)}
        </caption>
        <thead>
          <tr>
            <th scope="col">${msg('Idea')}</th>
            <th scope="col">n</th>
            <th scope="col">${msg('Before')}</th>
            <th scope="col">${msg('After')}</th>
            <th scope="col">⟨g⟩</th>
          </tr>
        </thead>
        <tbody>
          ${group.rows.map(
            (row) => html`<tr class=${row.concept === null ? 'whole' : ''} data-concept=${row.concept ?? ''}>
              <th scope="row">${concept(row)}</th>
              <td>${row.n}</td>
              <td>${row.pre === null ? '–' : formatPercent(row.pre)}</td>
              <td>${row.post === null ? '–' : formatPercent(row.post)}</td>
              <td>${row.gain === null ? '–' : number.format(row.gain)}</td>
            </tr>`,
          )}
        </tbody>
      </table>
      ${
        group.preOnly + group.postOnly > 0
          ? html`<p>${msg(str`Not counted: ${studentsCounted(group.preOnly)} with only the test before, ${group.postOnly} with only the test after.`)}</p>`
          : nothing
      }`;
  }
}

customElements.define('rt-dashboard-gain', RtDashboardGain);

declare global {
  interface HTMLElementTagNameMap {
    'rt-dashboard-gain': RtDashboardGain;
  }
}
