import { msg, str } from '@lit/localize';
import { css, html } from 'lit';
import { LocalizedElement } from '../../controls/localized-element.ts';
import type { ScaleSummary, SurveySummary } from '../../../classroom/dashboard-survey.ts';
import { localize, type Locale } from '../../../quest/localized-text.ts';
import './rt-dashboard-likert.ts';

/** Scales that share their steps and end labels go into one chart with one legend. */
function groupScales(scales: readonly ScaleSummary[]): ScaleSummary[][] {
  const groups = new Map<string, ScaleSummary[]>();
  for (const scale of scales) {
    const key = JSON.stringify([scale.min, scale.max, scale.minLabel, scale.maxLabel]);
    groups.set(key, [...(groups.get(key) ?? []), scale]);
  }
  return [...groups.values()];
}

/**
 * @summary One survey's answers for the whole class: scales as stacked Likert bars (one chart
 * per kind of scale), choices and numbers as small tables, free-text remarks in a
 * collapsible list.
 */
export class RtDashboardSurvey extends LocalizedElement {
  static override properties = { summary: { attribute: false }, locale: {} };

  static override styles = css`
    :host {
      display: flex;
      flex-direction: column;
      gap: calc(var(--rt-space) * 2);
    }
    h3 {
      font-size: 1rem;
      margin: 0 0 var(--rt-space);
    }
    table {
      border-collapse: collapse;
      font-size: 0.9rem;
      font-variant-numeric: tabular-nums;
    }
    th,
    td {
      padding: 3px 10px 3px 0;
      text-align: left;
      border-bottom: 1px solid var(--rt-border);
      vertical-align: top;
    }
    caption {
      text-align: left;
    }
    td.number {
      text-align: right;
    }
    .tables {
      display: flex;
      flex-wrap: wrap;
      align-items: start;
      gap: calc(var(--rt-space) * 3);
    }
    summary {
      cursor: pointer;
      min-height: var(--rt-target);
      display: flex;
      align-items: center;
    }
    summary:focus-visible {
      outline: 3px solid var(--rt-focus);
      outline-offset: 2px;
    }
    blockquote {
      margin: 4px 0;
      padding: 4px 10px;
      border-left: 3px solid var(--rt-border);
      white-space: pre-wrap;
    }
  `;

  declare summary: SurveySummary | null;
  declare locale: Locale;

  constructor() {
    super();
    this.summary = null;
    this.locale = 'en';
  }

  override render() {
    const survey = this.summary;
    if (!survey) return null;
    const t = (value: Parameters<typeof localize>[0]) => localize(value, this.locale);
    return html`
      ${groupScales(survey.scales).map(
        (group) => html`<section>
          <h3>${msg(str`From "${t(group[0].minLabel)}" to "${t(group[0].maxLabel)}"`)}</h3>
          <rt-dashboard-likert .scales=${group} .locale=${this.locale} caption=${msg(str`Answers from ${t(group[0].minLabel)} to ${t(group[0].maxLabel)}`)}></rt-dashboard-likert>
        </section>`,
      )}
      <div class="tables">
        ${survey.choices.map(
          (choice) => html`<table data-question=${choice.id}>
            <caption>
              <h3>${t(choice.text)}</h3>
            </caption>
            <tbody>
              ${choice.options.map((option) => html`<tr><th scope="row">${t(option.text)}</th><td class="number">${option.count}</td></tr>`)}
            </tbody>
          </table>`,
        )}
        ${
          survey.numbers.length
            ? html`<table>
              <caption>
                <h3>${msg('Numbers')}</h3>
              </caption>
              <thead>
                <tr>
                  <th scope="col">${msg('Question')}</th>
                  <th scope="col">${msg('Answers')}</th>
                  <th scope="col">${msg('Median')}</th>
                  <th scope="col">${msg('Range')}</th>
                </tr>
              </thead>
              <tbody>
                ${survey.numbers.map(
                  (number) => html`<tr>
                    <th scope="row">${t(number.text)}</th>
                    <td class="number">${number.stats?.count ?? 0}</td>
                    <td class="number">${number.stats ? number.stats.median : '–'}</td>
                    <td class="number">${number.stats ? `${number.stats.min} – ${number.stats.max}` : '–'}</td>
                  </tr>`,
                )}
              </tbody>
            </table>`
            : null
        }
      </div>
      ${survey.texts.map(
        (question) => html`<details>
          <summary>${t(question.text)} (${question.answers.length})</summary>
          ${question.answers.map((answer) => html`<blockquote>${answer}</blockquote>`)}
        </details>`,
      )}
    `;
  }
}

customElements.define('rt-dashboard-survey', RtDashboardSurvey);

declare global {
  interface HTMLElementTagNameMap {
    'rt-dashboard-survey': RtDashboardSurvey;
  }
}
