import { msg, str } from '@lit/localize';
import { css, html, nothing } from 'lit';
import type { PathVertexRow } from '../../../debugger/path-steps.ts';
import type { Color } from '../../../scene/scene.ts';
import { colorText } from './debug-numbers.ts';
import { eventName, lightSampleText, pathNumber } from './path-debugger-text.ts';

/**
 * The path debugger's numbers at 1366×768 (issue 42: the six-column table wrapped every
 * colour over two lines): the current vertex's estimate written out once above a table
 * of one line per vertex — its event, the throughput so far, what it added, and the path's
 * sum, which is the Added column summed and ends at the path's contribution.
 */

/** The current vertex: the factor f·cosθ/pdf it multiplied the throughput by, and what its light samples found. */
export function vertexEstimate(row: PathVertexRow) {
  return html`<ul class="estimate">
    ${
      row.factor
        ? html`<li title=${msg('L = Le + f·cosθ·Li / pdf, unrolled along the path: the throughput carries each factor f·cosθ/pdf; the light found is added times the throughput.')}>
          f·cosθ/pdf = ${colorText(row.factor)}${
            row.cosTheta !== null && row.pdf !== null
              ? html` <span class="muted">(cosθ = ${pathNumber.format(row.cosTheta)}, pdf = ${pathNumber.format(row.pdf)})</span>`
              : nothing
          }${row.survival !== null ? html` <span class="muted">÷ ${pathNumber.format(row.survival)} (${msg('roulette')})</span>` : nothing}
        </li>`
        : nothing
    }
    ${row.lightSamples.map((sample) => html`<li>${lightSampleText(sample)}</li>`)}
    ${row.emitted.some((value) => value !== 0) ? html`<li>${msg(str`Met by this ray: ${colorText(row.emitted)}`)}</li>` : nothing}
  </ul>`;
}

/** One line per vertex up to the current one. */
export function pathTable(rows: readonly PathVertexRow[], vertex: number) {
  let before: Color = [0, 0, 0];
  return html`<table>
    <thead>
      <tr>
        <th>#</th>
        <th>${msg('Event')}</th>
        <th>${msg('Throughput so far')}</th>
        <th>${msg('Added here')}</th>
        <th>${msg('Path’s sum')}</th>
      </tr>
    </thead>
    <tbody>
      ${rows.slice(0, vertex + 1).map((row, i) => {
        const added = row.runningSum.map((value, c) => value - before[c]) as Color;
        before = row.runningSum;
        return html`<tr class=${i === vertex ? 'current' : ''}>
          <td>${i}</td>
          <td>${eventName(row.event)}${row.objectId ? ` · ${row.objectId}` : ''}${row.lightId ? ` · ${row.lightId}` : ''}</td>
          <td>${colorText(row.throughput)}</td>
          <td>${added.some((value) => value !== 0) ? `+ ${colorText(added)}` : '–'}</td>
          <td>${colorText(row.runningSum)}</td>
        </tr>`;
      })}
    </tbody>
  </table>`;
}

export const pathTableStyles = css`
  table {
    border-collapse: collapse;
    width: 100%;
    font-variant-numeric: tabular-nums;
  }
  th,
  td {
    text-align: left;
    vertical-align: top;
    padding: 2px 6px;
    border-bottom: 1px solid var(--rt-border, #ccc);
    white-space: nowrap;
  }
  /* The table scrolls to the current vertex in a short dock: its header stays above the rows. */
  th {
    position: sticky;
    top: 0;
    background: var(--rt-surface);
  }
  td:nth-child(2) {
    white-space: normal;
  }
  tr.current {
    background: var(--rt-highlight, rgba(255, 200, 0, 0.18));
  }
  ul.estimate {
    margin: 0;
    padding-left: 1.2em;
  }
`;
