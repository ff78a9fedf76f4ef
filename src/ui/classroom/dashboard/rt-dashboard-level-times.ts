import { msg, str } from '@lit/localize';
import { css, html } from 'lit';
import { DashboardChart } from './rt-dashboard-chart.ts';
import { tableStyles } from './rt-dashboard-chart-styles.ts';
import { formatDuration } from './rt-dashboard-format.ts';

/** One learner's row: their active time per level (in the columns' order), null where they never came. */
export interface LearnerLevelRow {
  learner: string;
  cells: ({ activeMs: number; passed: boolean } | null)[];
}

/**
 * @summary Time per level per learner: a table with a learner per row and a level per
 * column; each cell a bar (the level's longest time is the full width, so bars compare
 * within a column) with the time as text and a tick when the learner passed. Who was slow
 * where, and who stopped, at a glance; the numbers are in the cells for screen readers.
 */
export class RtDashboardLevelTimes extends DashboardChart<LearnerLevelRow> {
  static override properties = { ...DashboardChart.properties, levels: { attribute: false } };
  static override styles = [
    tableStyles,
    css`
      th,
      td {
        text-align: left;
        white-space: nowrap;
      }
      thead th {
        white-space: normal;
        min-width: 8em;
      }
      .cell {
        display: grid;
        grid-template-columns: 90px auto;
        align-items: center;
        gap: 6px;
      }
      .track {
        height: 10px;
        background: var(--rt-surface-2);
        border-radius: 3px;
        overflow: hidden;
      }
      .bar {
        height: 100%;
        background: var(--rt-accent);
      }
      .bar.open {
        background: repeating-linear-gradient(45deg, var(--rt-muted) 0 3px, transparent 3px 6px);
      }
      .none {
        color: var(--rt-muted);
      }
    `,
  ];

  /** The column headings: level titles, in the cells' order. */
  declare levels: readonly string[];

  constructor() {
    super();
    this.levels = [];
  }

  override render() {
    const longest = this.levels.map((_, column) => Math.max(1, ...this.rows.map((row) => row.cells[column]?.activeMs ?? 0)));
    return html`<table>
      <caption>
        ${this.caption}
      </caption>
      <thead>
        <tr>
          <th scope="col">${msg('Student')}</th>
          ${this.levels.map((level) => html`<th scope="col">${level}</th>`)}
        </tr>
      </thead>
      <tbody>
        ${this.rows.map(
          (row) => html`<tr>
            <th scope="row">${row.learner}</th>
            ${row.cells.map((cell, column) =>
              cell
                ? html`<td data-passed=${cell.passed ? 'true' : 'false'}>
                    <span class="cell">
                      <span class="track" aria-hidden="true"><span class="bar ${cell.passed ? '' : 'open'}" style="width: ${(100 * cell.activeMs) / longest[column]}%; display: block"></span></span>
                      <span>${formatDuration(cell.activeMs)} ${cell.passed ? html`<span title=${msg('passed')} aria-label=${msg('passed')}>✓</span>` : msg('(not passed)')}</span>
                    </span>
                  </td>`
                : html`<td class="none">–</td>`,
            )}
          </tr>`,
        )}
      </tbody>
    </table>`;
  }
}

/** How a learner is named in the chart: their code, or "anonymous" and the start of their install id. */
export function learnerLabel(learner: { participant: string; learnerId: string }): string {
  if (learner.participant) return learner.participant;
  const install = /^install:([0-9a-f]{8})/.exec(learner.learnerId);
  return install ? msg(str`anonymous ${install[1]}`) : learner.learnerId;
}

customElements.define('rt-dashboard-level-times', RtDashboardLevelTimes);

declare global {
  interface HTMLElementTagNameMap {
    'rt-dashboard-level-times': RtDashboardLevelTimes;
  }
}
