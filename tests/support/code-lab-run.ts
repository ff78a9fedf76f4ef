import type { LabAction } from '../../src/lab-state/lab-action.ts';
import type { CodeGoal } from '../../src/quest/code-labs/code-goal.ts';
import { gradeLab, type Vec3 } from '../../src/quest/code-labs/code-lab-grading.ts';
import { labCases } from '../../src/quest/code-labs/lab-cases.ts';
import { tracerHitSphere } from '../../src/quest/code-labs/ray-sphere-lab.ts';

/** A run of the lab with the tracer's own function as the learner's, graded and reported as the app reports a run. */
export function tracerRun(goal: CodeGoal): LabAction {
  const { cases, tolerance } = labCases(goal);
  const outcomes = cases.map((labCase) => ({ returned: tracerHitSphere(...(labCase.args as [Vec3, Vec3, Vec3, number])) }));
  const report = gradeLab(cases, outcomes, tolerance);
  return { type: 'code.graded', lab: goal.code.lab, passed: report.passed, total: report.total, failed: report.firstFailure?.labCase.kind ?? null };
}
