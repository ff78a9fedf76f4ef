import { msg } from '@lit/localize';
import { css, html } from 'lit';
import { completionRate, isOptionalTask, type TaskSummary } from '../../../classroom/dashboard-summary.ts';
import { DashboardChart } from './rt-dashboard-chart.ts';
import { tableStyles } from './rt-dashboard-chart-styles.ts';
import { formatDuration, formatPercent } from './rt-dashboard-format.ts';

/**
 * @summary Where learners got stuck, per task: how many saw it and finished it, the median
 * and middle half of their times, hints (learners who opened one, and rungs opened) and
 * "show me". A sticking point (`stuck`, from classroom/dashboard-stuck.ts, whose rule the
 * page explains) is marked with a word and an icon, not colour alone.
 */
export class RtDashboardStuck extends DashboardChart<TaskSummary & { stuck: boolean }> {
  static override styles = [
    tableStyles,
    css`
      table {
        width: 100%;
      }
      th,
      td {
        text-align: right;
      }
      th:first-child,
      td:first-child {
        text-align: left;
      }
      td {
        white-space: nowrap;
      }
      tr.stuck td {
        background: color-mix(in srgb, var(--rt-warning) 14%, transparent);
      }
      .muted {
        color: var(--rt-muted);
        font-weight: normal;
      }
      .flag {
        color: var(--rt-warning);
        font-weight: 600;
        margin-left: 6px;
        white-space: nowrap;
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
          <th scope="col">${msg('Task')}</th>
          <th scope="col" title=${msg('Students who were shown the task')}>${msg('Students')}</th>
          <th scope="col" title=${msg('Done by the student or shown by "show me"')}>${msg('Completed')}</th>
          <th scope="col" title=${msg('Median active time of those who completed it')}>${msg('Median')}</th>
          <th scope="col" title=${msg('From the first to the third quartile: the middle half of the students')}>${msg('Middle half')}</th>
          <th scope="col" title=${msg('Students who opened at least one hint')}>${msg('Needed a hint')}</th>
          <th scope="col" title=${msg('Text hints and guidance (pointing at the control) opened, in total')}>${msg('Hints / guidance')}</th>
          <th scope="col" title=${msg('Students who let the app do the task')}>${msg('Show me')}</th>
        </tr>
      </thead>
      <tbody>
        ${this.rows.map((task) => {
          const { stuck } = task;
          return html`<tr class=${stuck ? 'stuck' : ''} data-task=${task.task}>
            <th scope="row">
              ${task.task}${isOptionalTask(task) ? html` <span class="muted">(${msg('optional')})</span>` : ''}
              ${stuck ? html`<span class="flag">⚠ ${msg('sticking point')}</span>` : null}
            </th>
            <td>${task.learners}</td>
            <td>${task.done + task.shown} (${formatPercent(completionRate(task))})</td>
            <td>${task.stats ? formatDuration(task.stats.median) : '–'}</td>
            <td>${task.stats ? `${formatDuration(task.stats.q1)} – ${formatDuration(task.stats.q3)}` : '–'}</td>
            <td>${task.learnersWithHints}</td>
            <td>${task.hintsText} / ${task.hintsGuidance}</td>
            <td>${task.shown}</td>
          </tr>`;
        })}
      </tbody>
    </table>`;
  }
}

customElements.define('rt-dashboard-stuck', RtDashboardStuck);

declare global {
  interface HTMLElementTagNameMap {
    'rt-dashboard-stuck': RtDashboardStuck;
  }
}
