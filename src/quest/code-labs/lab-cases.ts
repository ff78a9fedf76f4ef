import type { CodeGoal } from './code-goal.ts';
import type { LabCase, Tolerance } from './code-lab-grading.ts';
import type { RandomRun } from './code-lab-statistics.ts';
import { COSINE_BOUNCE_SIGNIFICANCE, cosineBounceRuns } from './cosine-bounce-lab.ts';
import type { DirectionRun } from './direction-statistics.ts';
import { MIRROR_TOLERANCE, mirrorCases } from './mirror-lab.ts';
import { PHONG_TOLERANCE, phongCases } from './phong-lab.ts';
import { PIXEL_SAMPLES_SIGNIFICANCE, pixelSampleRuns } from './pixel-samples-lab.ts';
import { RAY_BOX_TOLERANCE, rayBoxCases } from './ray-box-lab.ts';
import { RAY_SPHERE_TOLERANCE, raySphereCases } from './ray-sphere-lab.ts';
import { REFRACTION_TOLERANCE, refractionCases } from './refraction-lab.ts';
import { SHADOW_TOLERANCE, shadowCases } from './shadow-lab.ts';

/**
 * How a code goal is graded, as its lab says: cases compared one by one with the tracer's
 * answers within a tolerance (code-lab-grading.ts), or runs of a random function tested as a
 * sample at a significance: points in a pixel (code-lab-statistics.ts) or directions around
 * a normal (direction-statistics.ts).
 */
export type LabGrading =
  | { kind: 'cases'; cases: LabCase[]; tolerance: Tolerance }
  | { kind: 'statistics'; runs: RandomRun[]; significance: number }
  | { kind: 'directions'; runs: DirectionRun[]; normals: number; significance: number };

export function labCases(goal: CodeGoal): LabGrading {
  const code = goal.code;
  switch (code.lab) {
    case 'ray-sphere':
      return { kind: 'cases', cases: raySphereCases(code.cases.edges, code.cases.random, code.cases.seed), tolerance: RAY_SPHERE_TOLERANCE };
    case 'mirror':
      return { kind: 'cases', cases: mirrorCases(code.cases.edges, code.cases.random, code.cases.seed), tolerance: MIRROR_TOLERANCE };
    case 'refraction':
      return { kind: 'cases', cases: refractionCases(code.cases.edges, code.cases.random, code.cases.seed), tolerance: REFRACTION_TOLERANCE };
    case 'ray-box':
      return { kind: 'cases', cases: rayBoxCases(code.cases.edges, code.cases.random, code.cases.seed), tolerance: RAY_BOX_TOLERANCE };
    case 'shadow':
      return { kind: 'cases', cases: shadowCases(code.cases.edges, code.cases.random, code.cases.seed), tolerance: SHADOW_TOLERANCE };
    case 'phong':
      return { kind: 'cases', cases: phongCases(code.cases.edges, code.cases.random, code.cases.seed), tolerance: PHONG_TOLERANCE };
    case 'pixel-samples':
      return { kind: 'statistics', runs: pixelSampleRuns(code.cases.sizes, code.cases.runs, code.cases.seed), significance: PIXEL_SAMPLES_SIGNIFICANCE };
    case 'cosine-bounce': {
      const { normals, samples, seed } = code.cases;
      return { kind: 'directions', runs: cosineBounceRuns(normals, samples, seed), normals: normals.length, significance: COSINE_BOUNCE_SIGNIFICANCE };
    }
  }
}
