import type { CaseDrawing } from './case-drawing.ts';
import type { CodeGoal } from './code-goal.ts';
import type { CaseFailure, LabCase } from './code-lab-grading.ts';
import { drawMirrorCase } from './mirror-lab.ts';
import { drawPhongCase } from './phong-lab.ts';
import { drawRayBoxCase } from './ray-box-lab.ts';
import { drawRaySphereCase } from './ray-sphere-lab.ts';
import { drawRefractionCase } from './refraction-lab.ts';
import { drawShadowCase } from './shadow-lab.ts';

/** A lab's hook for the 3D view: its failing case as rays, points and shapes (case-drawing.ts). */
export type CaseDrawer = (labCase: LabCase, failure: CaseFailure | null) => CaseDrawing;

/**
 * Each lab's drawer, from its own `<lab>-lab.ts`. A lab without one is graded all the same;
 * its failing case is spelled out in the panel but not drawn. The samples lab fails on a
 * whole run, not a case: its drawer is drawSampleRun (pixel-samples-lab.ts).
 */
const DRAWERS: Partial<Record<CodeGoal['code']['lab'], CaseDrawer>> = {
  'ray-sphere': drawRaySphereCase,
  mirror: drawMirrorCase,
  refraction: drawRefractionCase,
  'ray-box': drawRayBoxCase,
  shadow: drawShadowCase,
  phong: drawPhongCase,
};

/** The first failing case of a run drawn as its lab draws it, or null when the lab draws none. */
export function drawFailingCase(goal: CodeGoal, failure: CaseFailure): CaseDrawing | null {
  return DRAWERS[goal.code.lab]?.(failure.labCase, failure) ?? null;
}
