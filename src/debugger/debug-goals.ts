import type { DebuggerRay, DebuggerTerm } from '../lab-state/lab-action.ts';
import { equationOf, type EquationTerm } from './debug-equation.ts';
import type { DebugProgram, DebugStep } from './debug-steps.ts';
import type { Scene } from '../scene/scene.ts';

/**
 * The debugger as the quest engine sees it: the ray a step reached (what `debugger.stepped`
 * reports), and the first step or term that matches what a task asks ("show me" moves there;
 * a test proves every level's debugger solution is reachable this way).
 */

/** The ray step `step` highlights, as goals look at it; null for the pixel's average. */
export function debuggerRayOf(step: DebugStep): DebuggerRay | null {
  const ray = step.ray;
  if (!ray) return null;
  return { type: ray.type, depth: step.depth, hit: ray.hit, objectId: ray.objectId, lightId: ray.lightId, from: step.from?.objectId ?? null };
}

/** The first step (from `after` on) whose ray has every field of `want`, or −1. */
export function findStep(program: DebugProgram, want: Partial<DebuggerRay>, after = 0): number {
  for (let index = after; index < program.steps.length; index++) {
    const ray = debuggerRayOf(program.steps[index]);
    if (ray && Object.entries(want).every(([field, value]) => ray[field as keyof DebuggerRay] === value)) return index;
  }
  return -1;
}

/** The first shade step whose equation has a term of `kind` (of `lightId`, if given) that comes from a ray. */
export function findTerm(program: DebugProgram, scene: Scene, kind: DebuggerTerm, lightId: string | null = null): { step: number; term: EquationTerm } | null {
  for (let index = 0; index < program.steps.length; index++) {
    const step = program.steps[index];
    if (step.kind !== 'shade' || !step.hit) continue;
    const term = equationOf(step.hit, scene)?.terms.find(
      (candidate) => candidate.kind === kind && candidate.ray && (lightId === null || candidate.lightId === lightId),
    );
    if (term) return { step: index, term };
  }
  return null;
}
