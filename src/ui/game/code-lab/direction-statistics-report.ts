import { msg, str } from '@lit/localize';
import { html, type TemplateResult } from 'lit';
import type { DirectionFailure, DirectionReport, DirectionRun, DirectionTest } from '../../../quest/code-labs/direction-statistics.ts';
import { caseKindName, failedRunsLine } from './code-lab-texts.ts';
import { labNumber, labValue } from './lab-numbers.ts';

/** A p-value as a learner can read it: "p = 0.65", "p = 0.0012" (Dutch "p = 0,0012"), or "p < 10⁻¹⁰" for the ones a biased function gets. */
const pText = (p: number) => (p < 1e-10 ? 'p < 10⁻¹⁰' : `p = ${labNumber(p, 2)}`);

const measureName = (test: DirectionTest) => (test.measure === 'cos-theta' ? 'cos θ' : 'φ');

/**
 * The result of a run of the cosine-bounce lab (direction-statistics.ts), spelled out: what was
 * tested on how many runs and the worst χ² test; or the first run that failed, and why.
 */
export function directionReport(report: DirectionReport, runs: readonly DirectionRun[]): TemplateResult {
  const failure = report.firstFailure;
  const significance = labNumber(report.significance, 2);
  if (!failure) {
    const worst = report.tests.reduce((a, b) => (b.p < a.p ? b : a));
    return html`<p>
      ${msg(str`${report.runs} runs: every direction of length 1, on the normal’s side, the same for the same random.`)}
      ${msg(str`cos θ and φ follow the cosine density for every normal (${report.tests.length} χ² tests, each failing below p = ${significance}; the lowest: ${pText(worst.p)}).`)}
    </p>`;
  }
  return html`<p class="fail">${failedRunsLine(report)}</p>
    <p>${failureText(failure, runs, significance)}</p>`;
}

function failureText(failure: DirectionFailure, runs: readonly DirectionRun[], significance: string): string {
  if ('test' in failure) {
    const { test } = failure;
    const chi = msg(
      str`χ² of ${measureName(test)} = ${labNumber(test.value, 3)} with ${test.degrees} degrees of freedom, ${pText(test.p)} (below ${significance} fails).`,
    );
    const why =
      failure.check === 'uneven-cos-theta'
        ? msg(
            'Every direction is a unit vector on the normal’s side, but their angles to the normal are not spread as cos θ / π asks: too many or too few lie near the surface. Is the disc point’s radius √u, and its height √(1 − r²)?',
          )
        : msg('Every direction is a unit vector on the normal’s side, but they do not go round the normal evenly: is φ = 2π · random(), a whole turn?');
    return `${caseKindName(test.normal)}: ${why} ${chi}`;
  }
  const run = failure.run + 1;
  const normal = runs[failure.run]?.args[0];
  const where = normal ? msg(str`Run ${run}, normal ${labValue(normal)}`) : msg(str`Run ${run}`);
  switch (failure.check) {
    case 'threw':
      return failure.line
        ? msg(str`${where}: your function threw ${failure.message} at line ${failure.line}.`)
        : msg(str`${where}: your function threw ${failure.message}.`);
    case 'not-a-vector':
      return msg(str`${where}: got ${labValue(failure.got)}, where a direction vec(x, y, z) of three numbers was expected.`);
    case 'not-unit':
      return msg(
        str`${where}: got ${labValue(failure.direction)} of length ${labNumber(failure.length, 12)}, where a direction of length 1 was expected. Normalize it, or check that the height is √(1 − r²).`,
      );
    case 'below-surface':
      return msg(
        str`${where}: got ${labValue(failure.direction)}, which goes into the surface (cos θ = ${labNumber(failure.cosTheta, 3)} is below 0). Build the direction around the given normal, in its half of the sphere.`,
      );
    case 'not-seeded':
      return msg(str`${where} gets the same random as run ${failure.repeats + 1} but gave another direction. Use the random you are given, not Math.random.`);
  }
}
