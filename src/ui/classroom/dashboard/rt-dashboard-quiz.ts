import { msg, str } from '@lit/localize';
import { css, html } from 'lit';
import type { QuizSummary } from '../../../classroom/dashboard-quiz.ts';
import { optionId } from '../../../classroom/quiz-options.ts';
import { DashboardChart } from './rt-dashboard-chart.ts';
import { namedRowsTableStyles, tableStyles } from './rt-dashboard-chart-styles.ts';
import { formatPercent } from './rt-dashboard-format.ts';

/**
 * @summary Quiz results per question (classroom/dashboard-quiz.ts): how many learners
 * answered (n), the share whose first answer was right, and each wrong option with how many
 * chose it, most chosen first, by its text (a picture quiz's option by its letter).
 */
export class RtDashboardQuiz extends DashboardChart<QuizSummary> {
  static override styles = [
    tableStyles,
    namedRowsTableStyles,
    css`
      td.number {
        text-align: right;
        white-space: nowrap;
      }
      ul {
        margin: 0;
        padding-left: 1.2em;
      }
      .muted {
        color: var(--rt-muted);
      }
    `,
  ];

  override render() {
    return html`<table>
      <caption>
        ${this.caption}
      </caption>
      <thead>
        <tr>
          <th scope="col">${msg('Question')}</th>
          <th scope="col" title=${msg('Students who answered; each counts once, with their first answer')}>n</th>
          <th scope="col" title=${msg('Students whose first answer was right')}>${msg('Right')}</th>
          <th scope="col">${msg('Wrong answers chosen (students)')}</th>
        </tr>
      </thead>
      <tbody>
        ${this.rows.map((quiz) => {
          const wrong = quiz.options.filter((option) => !option.right && option.learners > 0).sort((a, b) => b.learners - a.learners);
          return html`<tr data-task=${quiz.task}>
            <th scope="row">${quiz.question}</th>
            <td class="number">${quiz.learners}</td>
            <td class="number">${quiz.right} (${formatPercent(quiz.right / quiz.learners)})</td>
            <td>
              ${
                wrong.length === 0
                  ? html`<span class="muted">${msg('none')}</span>`
                  : html`<ul>
                    ${wrong.map(
                      (option) =>
                        html`<li>
                          ${quiz.pictures ? msg(str`picture ${optionId(option.position)}`) : `${optionId(option.position)}. ${option.text}`}:
                          <strong>${option.learners}</strong>
                        </li>`,
                    )}
                  </ul>`
              }
            </td>
          </tr>`;
        })}
      </tbody>
    </table>`;
  }
}

customElements.define('rt-dashboard-quiz', RtDashboardQuiz);

declare global {
  interface HTMLElementTagNameMap {
    'rt-dashboard-quiz': RtDashboardQuiz;
  }
}
