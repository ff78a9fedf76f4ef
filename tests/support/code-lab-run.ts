import type { LabAction } from '../../src/lab-state/lab-action.ts';
import type { CodeGoal, CodeLab } from '../../src/quest/code-labs/code-goal.ts';
import { gradeLab, type Vec3 } from '../../src/quest/code-labs/code-lab-grading.ts';
import { labCases } from '../../src/quest/code-labs/lab-cases.ts';
import { tracerHitBox } from '../../src/quest/code-labs/ray-box-lab.ts';
import { tracerHitSphere } from '../../src/quest/code-labs/ray-sphere-lab.ts';

/** Each lab's reference: the tracer's own function, called with a case's arguments. */
const TRACER_FUNCTIONS: Record<CodeLab, (args: unknown[]) => unknown> = {
  'ray-sphere': (args) => tracerHitSphere(...(args as [Vec3, Vec3, Vec3, number])),
  'ray-box': (args) => tracerHitBox(...(args as [Vec3, Vec3, Vec3, Vec3])),
};

/** A run of the lab with the tracer's own function as the learner's, graded and reported as the app reports a run. */
export function tracerRun(goal: CodeGoal): LabAction {
  const { cases, tolerance } = labCases(goal);
  const outcomes = cases.map((labCase) => ({ returned: TRACER_FUNCTIONS[goal.code.lab](labCase.args) }));
  const report = gradeLab(cases, outcomes, tolerance);
  return { type: 'code.graded', lab: goal.code.lab, passed: report.passed, total: report.total, failed: report.firstFailure?.labCase.kind ?? null };
}
