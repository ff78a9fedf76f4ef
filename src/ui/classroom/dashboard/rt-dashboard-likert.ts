import { msg, str } from '@lit/localize';
import { css, html, svg } from 'lit';
import { LocalizedElement } from '../../controls/localized-element.ts';
import type { ScaleSummary } from '../../../classroom/dashboard-survey.ts';
import { localize, type Locale } from '../../../quest/localized-text.ts';
import { chartStyles } from './rt-dashboard-chart-styles.ts';
import { formatPercent } from './rt-dashboard-format.ts';
import { PATTERN_DEFS, patternedRect, type PatternName } from './rt-dashboard-patterns.ts';

/** From "did not help" (red) through neutral grey to "helped a lot" (blue); readable with red-green colour blindness. */
const ENDS = { low: [215, 48, 39], middle: [200, 200, 200], high: [44, 123, 182] } as const;

/** The colour of step `index` of `steps`, interpolated through the neutral middle. */
function stepColor(index: number, steps: number): string {
  const position = steps === 1 ? 0.5 : index / (steps - 1);
  const [from, to, share] = position < 0.5 ? [ENDS.low, ENDS.middle, position * 2] : [ENDS.middle, ENDS.high, position * 2 - 1];
  const channel = (c: number) => Math.round(from[c] + (to[c] - from[c]) * share);
  return `rgb(${channel(0)} ${channel(1)} ${channel(2)})`;
}

/** Texture by side and distance from the middle: hatched below, dotted above, plain in the middle. */
function stepPattern(index: number, steps: number): PatternName {
  const offset = index - (steps - 1) / 2;
  if (Math.abs(offset) < 0.5) return null;
  const far = Math.abs(offset) > (steps - 1) / 4;
  if (offset < 0) return far ? 'hatch' : 'hatch-sparse';
  return far ? 'dots' : 'dots-sparse';
}

const HEIGHT = 26;
/** A segment narrower than this share of the bar has no room for its count (it is in the tooltip). */
const MIN_LABELLED_SHARE = 0.05;

/**
 * @summary Survey scales as stacked 100 % bars (the thesis's Figure 5.1): one bar per
 * question, one segment per step from the low end ("did not help") to the high end
 * ("helped a lot"), each with its count written in it and told apart by colour and texture;
 * a legend names the steps. Give it questions that share one scale.
 */
export class RtDashboardLikert extends LocalizedElement {
  static override properties = { scales: { attribute: false }, locale: {}, caption: {} };

  static override styles = [
    chartStyles,
    css`
      .bars {
        display: grid;
        grid-template-columns: minmax(160px, 320px) 1fr auto;
        align-items: center;
        gap: 6px var(--rt-space);
      }
      .question {
        font-size: 0.9rem;
      }
      .answered {
        font-size: 0.85rem;
        color: var(--rt-muted);
        font-variant-numeric: tabular-nums;
      }
      svg.bar {
        height: ${HEIGHT}px;
      }
      .count {
        font-size: 12px;
        font-weight: 600;
        paint-order: stroke;
        stroke: rgb(255 255 255 / 85%);
        stroke-width: 3px;
        fill: #111;
      }
    `,
  ];

  declare scales: readonly ScaleSummary[];
  declare locale: Locale;
  declare caption: string;

  constructor() {
    super();
    this.scales = [];
    this.locale = 'en';
    this.caption = '';
  }

  override render() {
    const first = this.scales[0];
    if (!first) return null;
    const steps = first.max - first.min + 1;
    const stepName = (index: number) => {
      const value = first.min + index;
      if (index === 0) return `${value} – ${localize(first.minLabel, this.locale)}`;
      if (index === steps - 1) return `${value} – ${localize(first.maxLabel, this.locale)}`;
      return String(value);
    };
    return html`${PATTERN_DEFS}
      <div class="bars" role="list" aria-label=${this.caption}>
        ${this.scales.map((scale) => {
          const question = localize(scale.text, this.locale);
          const share = (count: number) => (scale.answered === 0 ? 0 : count / scale.answered);
          const summary = scale.counts.map((count, index) => `${stepName(index)}: ${count} (${formatPercent(share(count))})`).join(', ');
          let x = 0;
          return html`<div class="question">${question}</div>
            <svg class="bar" role="listitem" aria-label=${`${question} ${summary}`} data-question=${scale.id}>
              <title>${summary}</title>
              ${scale.counts.map((count, index) => {
                if (count === 0) return null;
                const width = 100 * share(count);
                const segment = svg`${patternedRect(`${x}%`, 0, `${width}%`, HEIGHT, stepColor(index, steps), stepPattern(index, steps), `segment step-${index}`)}
                  ${share(count) >= MIN_LABELLED_SHARE ? svg`<text class="count" x="${x + width / 2}%" y=${HEIGHT / 2 + 4} text-anchor="middle">${count}</text>` : null}`;
                x += width;
                return segment;
              })}
            </svg>
            <span class="answered">${msg(str`n = ${scale.answered}`)}</span>`;
        })}
      </div>
      <ul class="legend" aria-label=${msg('Scale')}>
        ${Array.from(
          { length: steps },
          (_, index) =>
            html`<li><svg viewBox="0 0 22 14" aria-hidden="true">${patternedRect(0, 0, 22, 14, stepColor(index, steps), stepPattern(index, steps))}</svg> ${stepName(index)}</li>`,
        )}
      </ul>`;
  }
}

customElements.define('rt-dashboard-likert', RtDashboardLikert);

declare global {
  interface HTMLElementTagNameMap {
    'rt-dashboard-likert': RtDashboardLikert;
  }
}
