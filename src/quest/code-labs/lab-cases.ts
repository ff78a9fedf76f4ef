import type { CodeGoal } from './code-goal.ts';
import type { LabCase, Tolerance } from './code-lab-grading.ts';
import { RAY_BOX_TOLERANCE, rayBoxCases } from './ray-box-lab.ts';
import { RAY_SPHERE_TOLERANCE, raySphereCases } from './ray-sphere-lab.ts';

/** The cases a code goal is graded on, and the tolerance its answers are compared within: its lab's grader, as the level asks. */
export function labCases(goal: CodeGoal): { cases: LabCase[]; tolerance: Tolerance } {
  const code = goal.code;
  switch (code.lab) {
    case 'ray-sphere':
      return { cases: raySphereCases(code.cases.edges, code.cases.random, code.cases.seed), tolerance: RAY_SPHERE_TOLERANCE };
    case 'ray-box':
      return { cases: rayBoxCases(code.cases.edges, code.cases.random, code.cases.seed), tolerance: RAY_BOX_TOLERANCE };
  }
}
