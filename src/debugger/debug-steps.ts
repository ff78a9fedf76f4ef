import type { Scene } from '../scene/scene.ts';
import type { PixelTrace, RayNode } from '../tracer/ray-tree.ts';
import type { PseudocodeLine } from './pseudocode.ts';

/**
 * What the tracer does at one step, as a debugger steps through code:
 * - cast: a ray leaves (primary, reflected or refracted) and grows to what it hits;
 * - shade: it hit a surface: colour ← ka·C + Σ la·Lc·C (the equation appears);
 * - light: a shadow ray toward one light (or one sample of an area light), reaching it or
 *   blocked; with Shadows off, the untested direction to it (no shadow ray is cast);
 * - split: glass: Schlick's kr and kt before its two rays;
 * - return: the ray's colour, clamped, goes back to its parent (or the background, for a miss);
 * - average: the samples' colours averaged into the pixel.
 */
export type StepKind = 'cast' | 'shade' | 'light' | 'split' | 'return' | 'average';

export interface DebugStep {
  kind: StepKind;
  line: PseudocodeLine;
  /** The ray highlighted in 3D: the one cast, or the hit being shaded or returned; null for the average. */
  ray: RayNode | null;
  /** The surface ray whose hit the equation shows: the ray itself, or the hit a light or child ray leaves from. */
  hit: RayNode | null;
  /** The hit `ray` leaves from: its parent (null for a primary ray). */
  from: RayNode | null;
  /** Recursion depth of `ray` (primary rays 0; a shadow ray has its hit's depth). */
  depth: number;
  /** Which supersample's tree (0 … s²−1). */
  sample: number;
}

/** A pixel's trace as the steps the tracer took, in its order (depth first, spec §2 of the debugger). */
export interface DebugProgram {
  trace: PixelTrace;
  steps: DebugStep[];
  /** For each step, the rays drawn by then (cast so far), as an index into `rays`: rays[0 … shownUpTo[i]). */
  shownUpTo: number[];
  /** Every ray in the order it is cast. */
  rays: RayNode[];
}

/** Whether the object a ray hit is glass (transparent), from the scene, or from its terms when the scene no longer has it. */
function isGlass(node: RayNode, scene: Scene): boolean {
  const object = scene.objects.find((candidate) => candidate.id === node.objectId);
  return object ? object.material.transparent : node.terms?.refract != null;
}

/** The steps of a pixel's trace (traced with terms, for the equation; without, the steps are the same). */
export function debugProgram(trace: PixelTrace, scene: Scene): DebugProgram {
  const steps: DebugStep[] = [];
  const rays: RayNode[] = [];
  const shownUpTo: number[] = [];
  const push = (step: DebugStep, casts: boolean) => {
    if (casts && step.ray) rays.push(step.ray);
    steps.push(step);
    shownUpTo.push(rays.length);
  };

  const visit = (node: RayNode, parent: RayNode | null, depth: number, sample: number, line: PseudocodeLine) => {
    const from = parent;
    push({ kind: 'cast', line, ray: node, hit: parent, from, depth, sample }, true);
    if (!node.hit) {
      push({ kind: 'return', line: 'nearest-hit', ray: node, hit: parent, from, depth, sample }, false);
      return;
    }
    push({ kind: 'shade', line: 'ambient', ray: node, hit: node, from, depth, sample }, false);
    const glass = isGlass(node, scene);
    let split = false;
    for (const child of node.children) {
      if (child.type === 'reflect' || child.type === 'refract') {
        if (glass && !split) {
          push({ kind: 'split', line: 'schlick', ray: node, hit: node, from, depth, sample }, false);
          split = true;
        }
        visit(child, node, depth + 1, sample, glass ? 'glass' : 'mirror');
      } else {
        const blocked = child.type === 'shadow' || child.type === 'area-shadow';
        push({ kind: 'light', line: blocked ? 'blocked' : 'lit', ray: child, hit: node, from: node, depth, sample }, true);
      }
    }
    push({ kind: 'return', line: 'return', ray: node, hit: node, from, depth, sample }, false);
  };

  trace.rays.forEach((root, sample) => visit(root, null, 0, sample, 'trace-primary'));
  push({ kind: 'average', line: 'average', ray: null, hit: null, from: null, depth: 0, sample: trace.rays.length - 1 }, false);
  return { trace, steps, shownUpTo, rays };
}

/** The step on which `ray` is cast (where clicking a term jumps the highlight to), or −1. */
export function stepCasting(program: DebugProgram, ray: RayNode): number {
  return program.steps.findIndex((step) => (step.kind === 'cast' || step.kind === 'light') && step.ray === ray);
}

/** The rays drawn at step `index`: those cast so far. */
export function raysShownAt(program: DebugProgram, index: number): RayNode[] {
  return program.rays.slice(0, program.shownUpTo[index] ?? 0);
}

/**
 * The cursor's next position for a key or button: forward and back one step, to the start,
 * to the end. It stays in 0 … steps − 1.
 */
export function moveCursor(program: DebugProgram, index: number, move: 'step' | 'back' | 'reset' | 'end'): number {
  const last = program.steps.length - 1;
  switch (move) {
    case 'step':
      return Math.min(last, index + 1);
    case 'back':
      return Math.max(0, index - 1);
    case 'reset':
      return 0;
    case 'end':
      return last;
  }
}
