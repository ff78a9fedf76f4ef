import type { LabAction } from '../../src/lab-state/lab-action.ts';
import type { CodeGoal } from '../../src/quest/code-labs/code-goal.ts';
import { gradeLab } from '../../src/quest/code-labs/code-lab-grading.ts';
import { labCases } from '../../src/quest/code-labs/lab-cases.ts';

/** A run of the lab with the tracer's own answers (each lab's `expected`) as the learner's, graded and reported as the app reports a run. */
export function tracerRun(goal: CodeGoal): LabAction {
  const { cases, tolerance } = labCases(goal);
  // Through a copy, as the sandbox sends them back: plain data, not the tracer's own objects.
  const outcomes = cases.map((labCase) => ({ returned: structuredClone(labCase.expected) }));
  const report = gradeLab(cases, outcomes, tolerance);
  return { type: 'code.graded', lab: goal.code.lab, passed: report.passed, total: report.total, failed: report.firstFailure?.labCase.kind ?? null };
}
