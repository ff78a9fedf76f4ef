import { msg, str } from '@lit/localize';
import { css, html, svg } from 'lit';
import { axisEnd, type FiveNumbers } from '../../../classroom/dashboard-stats.ts';
import { studentsCounted } from '../../../i18n/counted.ts';
import { DashboardChart } from './rt-dashboard-chart.ts';
import { chartStyles } from './rt-dashboard-chart-styles.ts';
import { formatDuration } from './rt-dashboard-format.ts';

/** One row of the plot: a task (or a whole level) and every learner's time for it. */
export interface TimeRow {
  label: string;
  times: readonly number[];
  stats: FiveNumbers | null;
}

const WIDTH = 640;
const ROW_HEIGHT = 30;
const BOX_HEIGHT = 14;
const AXIS_HEIGHT = 22;
const PAD = 12;
/** Tick steps a teacher reads at a glance, from 10 s to an hour. */
const TICK_STEPS_MS = [10, 15, 30, 60, 120, 300, 600, 900, 1800, 3600].map((seconds) => seconds * 1000);
const MAX_TICKS = 7;

/** A step from TICK_STEPS_MS that gives at most MAX_TICKS ticks up to `max`. */
function tickStep(max: number): number {
  return TICK_STEPS_MS.find((step) => max / step <= MAX_TICKS) ?? Math.ceil(max / MAX_TICKS / 3_600_000) * 3_600_000;
}

/**
 * @summary Times per task as a box plot with every learner as a dot (a strip plot): the box
 * spans the middle half (quartiles), the thick line is the median, whiskers reach the
 * fastest and slowest. Dots are spread up and down so that equal times stay visible. Each
 * row names its numbers in a tooltip; the table beside it has them as text. The axis ends
 * at the longest time that is not an outlier (axisEnd); longer ones sit at its end as
 * hollow dots, and whiskers stop there with an arrow.
 */
export class RtDashboardTimes extends DashboardChart<TimeRow> {
  static override styles = [
    chartStyles,
    css`
      .plot {
        display: grid;
        grid-template-columns: minmax(120px, 220px) 1fr;
        align-items: center;
        column-gap: var(--rt-space);
      }
      svg {
        width: 100%;
        height: auto;
        display: block;
        overflow: visible;
      }
      .box {
        fill: var(--rt-accent-soft);
        stroke: var(--rt-accent);
        stroke-width: 1.5;
      }
      .median {
        stroke: var(--rt-text);
        stroke-width: 3;
      }
      .whisker {
        stroke: var(--rt-muted);
        stroke-width: 1.5;
      }
      .dot {
        fill: var(--rt-accent);
        fill-opacity: 0.55;
        stroke: var(--rt-surface);
        stroke-width: 0.75;
      }
      .dot.beyond {
        fill: none;
        stroke: var(--rt-accent);
        stroke-width: 1.5;
      }
      .grid {
        stroke: var(--rt-border);
      }
      .tick {
        fill: var(--rt-muted);
        font-size: 11px;
      }
      .none {
        fill: var(--rt-muted);
        font-size: 12px;
      }
    `,
  ];

  override render() {
    const max = Math.max(1000, axisEnd(this.rows));
    const step = tickStep(max);
    const end = Math.ceil(max / step) * step;
    const x = (ms: number) => PAD + ((WIDTH - 2 * PAD) * Math.min(ms, end)) / end;
    const ticks = Array.from({ length: Math.round(end / step) + 1 }, (_, index) => index * step);
    const grid = (height: number) => ticks.map((tick) => svg`<line class="grid" x1=${x(tick)} x2=${x(tick)} y1="0" y2=${height}></line>`);
    return html`<div class="plot" role="img" aria-label=${this.caption}>
      ${this.rows.map(
        (row) => html`<div class="label">${row.label}</div>
          <svg class="row" viewBox="0 0 ${WIDTH} ${ROW_HEIGHT}" data-label=${row.label} data-dots=${row.times.length}>
            <title>${row.stats ? describe(row.label, row.stats) : msg(str`${row.label}: nobody completed it`)}</title>
            ${grid(ROW_HEIGHT)} ${row.stats ? this.box(row.stats, x) : svg`<text class="none" x=${PAD} y=${ROW_HEIGHT / 2 + 4}>${msg('nobody completed it')}</text>`}
            ${row.times.map(
              (ms, index) =>
                // Golden-ratio spread: deterministic, and neighbours in the list land far apart.
                svg`<circle class="dot ${ms > end ? 'beyond' : ''}" cx=${x(ms)} cy=${ROW_HEIGHT / 2 + (((index * 0.618034) % 1) - 0.5) * (ROW_HEIGHT - 8)} r="3"></circle>`,
            )}
          </svg>`,
      )}
      <div></div>
      <svg viewBox="0 0 ${WIDTH} ${AXIS_HEIGHT}" aria-hidden="true">
        ${ticks.map((tick) => svg`<text class="tick" x=${x(tick)} y="14" text-anchor="middle">${formatDuration(tick)}</text>`)}
      </svg>
    </div>`;
  }

  private box(stats: FiveNumbers, x: (ms: number) => number) {
    const middle = ROW_HEIGHT / 2;
    const top = middle - BOX_HEIGHT / 2;
    return svg`
      <line class="whisker" x1=${x(stats.min)} x2=${x(stats.max)} y1=${middle} y2=${middle}></line>
      <line class="whisker" x1=${x(stats.min)} x2=${x(stats.min)} y1=${top + 3} y2=${top + BOX_HEIGHT - 3}></line>
      <line class="whisker" x1=${x(stats.max)} x2=${x(stats.max)} y1=${top + 3} y2=${top + BOX_HEIGHT - 3}></line>
      <rect class="box" x=${x(stats.q1)} y=${top} width=${Math.max(1, x(stats.q3) - x(stats.q1))} height=${BOX_HEIGHT}></rect>
      <line class="median" x1=${x(stats.median)} x2=${x(stats.median)} y1=${top - 2} y2=${top + BOX_HEIGHT + 2}></line>`;
  }
}

function describe(label: string, stats: FiveNumbers): string {
  return msg(
    str`${label}: median ${formatDuration(stats.median)}, middle half ${formatDuration(stats.q1)}–${formatDuration(stats.q3)}, fastest ${formatDuration(stats.min)}, slowest ${formatDuration(stats.max)} (${studentsCounted(stats.count)})`,
  );
}

customElements.define('rt-dashboard-times', RtDashboardTimes);

declare global {
  interface HTMLElementTagNameMap {
    'rt-dashboard-times': RtDashboardTimes;
  }
}
