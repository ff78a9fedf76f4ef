import type { CodeGoal } from './code-goal.ts';
import type { LabCase, Tolerance } from './code-lab-grading.ts';
import { MIRROR_TOLERANCE, mirrorCases } from './mirror-lab.ts';
import { REFRACTION_TOLERANCE, refractionCases } from './refraction-lab.ts';
import { RAY_SPHERE_TOLERANCE, raySphereCases } from './ray-sphere-lab.ts';

/** The cases a code goal is graded on, and the tolerance its answers are compared within: its lab's grader, as the level asks. */
export function labCases(goal: CodeGoal): { cases: LabCase[]; tolerance: Tolerance } {
  const code = goal.code;
  const { random, seed } = code.cases;
  switch (code.lab) {
    case 'ray-sphere':
      return { cases: raySphereCases(code.cases.edges, random, seed), tolerance: RAY_SPHERE_TOLERANCE };
    case 'mirror':
      return { cases: mirrorCases(code.cases.edges, random, seed), tolerance: MIRROR_TOLERANCE };
    case 'refraction':
      return { cases: refractionCases(code.cases.edges, random, seed), tolerance: REFRACTION_TOLERANCE };
  }
}
