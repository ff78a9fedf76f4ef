import type { LabAction } from '../../src/lab-state/lab-action.ts';
import type { CodeGoal } from '../../src/quest/code-labs/code-goal.ts';
import { gradeLab, type LabOutcome } from '../../src/quest/code-labs/code-lab-grading.ts';
import { gradeSamples, sampleTally } from '../../src/quest/code-labs/code-lab-statistics.ts';
import { tracerCosineDirection } from '../../src/quest/code-labs/cosine-bounce-lab.ts';
import { directionTally, gradeDirections } from '../../src/quest/code-labs/direction-statistics.ts';
import { labCases } from '../../src/quest/code-labs/lab-cases.ts';
import { tracerPixelSamples } from '../../src/quest/code-labs/pixel-samples-lab.ts';
import { RandomStream } from '../../src/tracer/sampler.ts';

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

/** A run of the lab with the tracer's own answers (each lab's `expected`) as the learner's, graded and reported as the app reports a run. */
export function tracerRun(goal: CodeGoal): LabAction {
  const grading = labCases(goal);
  if (grading.kind === 'statistics') {
    // A random function's runs have no one answer each: the tracer's own pattern is run on them.
    const outcomes = runCases(
      tracerPixelSamples,
      grading.runs.map((run) => run.args),
    );
    return { type: 'code.graded', lab: goal.code.lab, ...sampleTally(gradeSamples(grading.runs, outcomes, grading.significance)) };
  }
  if (grading.kind === 'directions') {
    const outcomes = runCases(
      tracerCosineDirection,
      grading.runs.map((run) => run.args),
    );
    return { type: 'code.graded', lab: goal.code.lab, ...directionTally(gradeDirections(grading.runs, outcomes, grading.significance), grading.normals) };
  }
  const { cases, tolerance } = grading;
  // Through a copy, as the sandbox sends them back: plain data, not the tracer's own objects.
  const outcomes = cases.map((labCase) => ({ returned: structuredClone(labCase.expected) }));
  const report = gradeLab(cases, outcomes, tolerance);
  return { type: 'code.graded', lab: goal.code.lab, passed: report.passed, total: report.total, failed: report.firstFailure?.labCase.kind ?? null };
}
