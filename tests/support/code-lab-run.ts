import type { LabAction } from '../../src/lab-state/lab-action.ts';
import type { CodeGoal, CodeLab } from '../../src/quest/code-labs/code-goal.ts';
import { gradeLab, type LabOutcome } from '../../src/quest/code-labs/code-lab-grading.ts';
import { gradeSamples, sampleTally } from '../../src/quest/code-labs/code-lab-statistics.ts';
import { labCases } from '../../src/quest/code-labs/lab-cases.ts';
import { tracerPixelSamples } from '../../src/quest/code-labs/pixel-samples-lab.ts';
import { tracerHitBox } from '../../src/quest/code-labs/ray-box-lab.ts';
import { tracerHitSphere } from '../../src/quest/code-labs/ray-sphere-lab.ts';
import { RandomStream } from '../../src/tracer/sampler.ts';

/** Each lab's reference: the tracer's own function, called with a case's arguments. */
const TRACER_FUNCTIONS: Record<CodeLab, (...args: never[]) => unknown> = {
  'ray-sphere': tracerHitSphere,
  'ray-box': tracerHitBox,
  'pixel-samples': tracerPixelSamples,
};

/**
 * Runs a function on every case's arguments, as the sandbox does in the browser: an argument
 * { seededRandom: seed } becomes a random function made from that seed (here the tracer's
 * generator; the sandbox page has one of its own), an exception becomes its case's outcome.
 */
export function runCases(learnerFunction: (...args: never[]) => unknown, cases: readonly unknown[][]): LabOutcome[] {
  return cases.map((args) => {
    const given = args.map((arg) => {
      const seed = (arg as { seededRandom?: unknown } | null)?.seededRandom;
      if (typeof seed !== 'number') return arg;
      const stream = new RandomStream().reset(seed);
      return () => stream.next();
    });
    try {
      return { returned: (learnerFunction as (...args: unknown[]) => unknown)(...given) };
    } catch (error) {
      return { threw: String(error), line: null };
    }
  });
}

/** A run of the lab with the tracer's own function as the learner's, graded and reported as the app reports a run. */
export function tracerRun(goal: CodeGoal): LabAction {
  const grading = labCases(goal);
  const reference = TRACER_FUNCTIONS[goal.code.lab];
  if (grading.kind === 'statistics') {
    const report = gradeSamples(
      grading.runs,
      runCases(
        reference,
        grading.runs.map((run) => run.args),
      ),
      grading.significance,
    );
    return { type: 'code.graded', lab: goal.code.lab, ...sampleTally(report) };
  }
  const report = gradeLab(
    grading.cases,
    runCases(
      reference,
      grading.cases.map((labCase) => labCase.args),
    ),
    grading.tolerance,
  );
  return { type: 'code.graded', lab: goal.code.lab, passed: report.passed, total: report.total, failed: report.firstFailure?.labCase.kind ?? null };
}
