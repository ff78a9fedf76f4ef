import { msg, str } from '@lit/localize';
import { html, type TemplateResult } from 'lit';
import type { RandomRun, SampleFailure, StatisticsReport } from '../../../quest/code-labs/code-lab-statistics.ts';
import { numberList } from '../../../i18n/number-format.ts';
import { failedRunsLine } from './code-lab-texts.ts';
import { labNumber } from './lab-numbers.ts';

/** A p-value as a learner can read it: "p = 0.65", "p = 0.0012" (Dutch "p = 0,0012"), or "p < 10⁻¹⁰" for the ones a biased function gets. */
const pText = (p: number) => (p < 1e-10 ? 'p < 10⁻¹⁰' : `p = ${labNumber(p, 2)}`);

/**
 * The result of a statistically graded run (code-lab-statistics.ts), spelled out: what was
 * tested on how many runs, and the χ² with its p-value; or the first run that failed, and why.
 */
export function statisticsReport(report: StatisticsReport, runs: readonly RandomRun[]): TemplateResult {
  const test = report.test;
  const failure = report.firstFailure;
  const chi = test
    ? msg(str`χ² = ${labNumber(test.value, 3)} with ${test.degrees} degrees of freedom, ${pText(test.p)} (below ${labNumber(test.significance, 2)} fails).`)
    : '';
  if (!failure && test) {
    return html`<p>${msg(str`${report.runs} runs, ${report.points} points: all in the pixel, one in every cell, the same for the same random, and spread evenly within their cells.`)} ${chi}</p>`;
  }
  return html`<p class="fail">${failedRunsLine(report)}</p>
    <p>${failure ? failureText(failure, runs) : ''} ${failure?.check === 'uneven-within-cells' ? chi : ''}</p>`;
}

function failureText(failure: SampleFailure, runs: readonly RandomRun[]): string {
  if (failure.check === 'uneven-within-cells') {
    return msg(
      'Every run is inside the pixel with one point in each cell, but the points do not spread evenly within their cells: is each point’s place in its cell uniform random, in x and in y?',
    );
  }
  const run = failure.run + 1;
  const n = runs[failure.run]?.args[0] ?? 0;
  switch (failure.check) {
    case 'threw':
      return failure.line
        ? msg(str`Run ${run} (n = ${n}): your function threw ${failure.message} at line ${failure.line}.`)
        : msg(str`Run ${run} (n = ${n}): your function threw ${failure.message}.`);
    case 'not-points':
      return msg(str`Run ${run} (n = ${n}): got ${failure.got}, where a point {x, y} with two numbers was expected. Return an array of n points.`);
    case 'wrong-count':
      return msg(str`Run ${run} (n = ${n}): got ${failure.got} points instead of ${failure.wanted}.`);
    case 'outside-pixel': {
      const point = `(${numberList([labNumber(failure.point.x), labNumber(failure.point.y)])})`;
      return msg(str`Run ${run} (n = ${n}): the point ${point} lies outside the pixel. x and y go from 0 up to, not including, 1.`);
    }
    case 'two-in-a-cell': {
      const [column, row] = failure.cell;
      return msg(
        str`Run ${run} (n = ${n}): two points in cell (${column}, ${row}) of the ${failure.cells} × ${failure.cells} grid, so another cell has none. Each cell gets exactly one point.`,
      );
    }
    case 'not-seeded':
      return msg(str`Run ${run} gets the same random as run ${failure.repeats + 1} but gave other points. Use the random you are given, not Math.random.`);
  }
}
