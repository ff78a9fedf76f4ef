import { msg, str } from '@lit/localize';
import { css, html, svg } from 'lit';
import { DashboardChart } from './rt-dashboard-chart.ts';
import { chartStyles } from './rt-dashboard-chart-styles.ts';
import { formatPercent } from './rt-dashboard-format.ts';
import { PATTERN_DEFS, patternedRect, type PatternName } from './rt-dashboard-patterns.ts';

/** One bar: a task's learners by how they finished it. */
export interface CompletionRow {
  label: string;
  learners: number;
  done: number;
  shown: number;
  skipped: number;
}

type Part = 'done' | 'shown' | 'skipped' | 'unfinished';
const PARTS: readonly { part: Part; fill: string; pattern: PatternName }[] = [
  { part: 'done', fill: 'var(--rt-success)', pattern: null },
  { part: 'shown', fill: 'var(--rt-warning)', pattern: 'hatch' },
  { part: 'skipped', fill: 'var(--rt-muted)', pattern: 'dots' },
  { part: 'unfinished', fill: 'transparent', pattern: null },
];

const partNames = (): Record<Part, string> => ({
  done: msg('done by the student'),
  shown: msg('shown by the app ("show me")'),
  skipped: msg('skipped (optional)'),
  unfinished: msg('not finished'),
});

const HEIGHT = 18;

/**
 * @summary Completion per task: one bar per task over the learners who saw it, split into
 * done / shown by "show me" / skipped / not finished, told apart by colour, texture and
 * the legend, with the count and share written next to each bar.
 */
export class RtDashboardCompletion extends DashboardChart<CompletionRow> {
  static override styles = [
    chartStyles,
    css`
      .bars {
        display: grid;
        grid-template-columns: minmax(120px, 220px) 1fr auto;
        align-items: center;
        gap: 4px var(--rt-space);
      }
      .count {
        font-variant-numeric: tabular-nums;
        font-size: 0.9rem;
      }
      svg.bar {
        height: ${HEIGHT}px;
      }
      .outline {
        stroke-dasharray: 3 2;
      }
    `,
  ];

  override render() {
    const names = partNames();
    return html`${PATTERN_DEFS}
      <div class="bars" role="list" aria-label=${this.caption}>
        ${this.rows.map((row) => {
          const counts: Record<Part, number> = { ...row, unfinished: Math.max(0, row.learners - row.done - row.shown - row.skipped) };
          const completed = row.done + row.shown;
          let x = 0;
          const summary = PARTS.map(({ part }) => `${counts[part]} ${names[part]}`).join(', ');
          return html`<div class="label">${row.label}</div>
            <svg class="bar" role="listitem" aria-label=${`${row.label}: ${summary}`} data-label=${row.label}>
              <title>${summary}</title>
              ${PARTS.map(({ part, fill, pattern }) => {
                const width = row.learners === 0 ? 0 : (100 * counts[part]) / row.learners;
                const rect = patternedRect(`${x}%`, 0, `${width}%`, HEIGHT, fill, pattern, `segment ${part}`);
                x += width;
                return counts[part] > 0 ? rect : null;
              })}
              ${svg`<rect class="outline" x="0" y="0" width="100%" height=${HEIGHT}></rect>`}
            </svg>
            <span class="count">${msg(str`${completed} of ${row.learners} (${formatPercent(row.learners ? completed / row.learners : 0)})`)}</span>`;
        })}
      </div>
      <ul class="legend">
        ${PARTS.map(
          ({ part, fill, pattern }) =>
            html`<li><svg viewBox="0 0 22 14" aria-hidden="true">${patternedRect(0, 0, 22, 14, fill, pattern)}${svg`<rect class="outline" x="0.5" y="0.5" width="21" height="13"></rect>`}</svg> ${names[part]}</li>`,
        )}
      </ul>`;
  }
}

customElements.define('rt-dashboard-completion', RtDashboardCompletion);

declare global {
  interface HTMLElementTagNameMap {
    'rt-dashboard-completion': RtDashboardCompletion;
  }
}
