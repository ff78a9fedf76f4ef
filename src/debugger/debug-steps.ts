import type { Color, Scene } from '../scene/scene.ts';
import type { PixelTrace, RayNode } from '../tracer/ray-tree.ts';
import type { PseudocodeLine } from './pseudocode.ts';

/**
 * What the tracer does at one step, as a debugger steps through code:
 * - sample: a pixel sample that casts several rays (a lens or an open shutter): its pinhole
 *   ray to the plane in focus, where its lens rays aim (distribution-effects §3);
 * - lens: one lens point of such a sample, when it is traced at several moments;
 * - cast: a ray leaves (primary, reflected or refracted) and grows to what it hits;
 * - shade: it hit a surface: colour ← ka·C + Σ la·Lc·C (the equation appears);
 * - light: a shadow ray toward one light (or one sample of an area light), reaching it or
 *   blocked; with Shadows off, the untested direction to it (no shadow ray is cast);
 * - split: glass: Schlick's kr and kt before its two rays;
 * - return: the ray's colour, clamped, goes back to its parent (or the background, for a miss);
 * - average: the rays' colours, each times its share, added into the pixel.
 */
export type StepKind = 'sample' | 'lens' | 'cast' | 'shade' | 'light' | 'split' | 'return' | 'average';

/** Where a step's ray sits among its siblings of one kind (1-based), for the tree's labels. */
export interface StepPlace {
  of: 'sample' | 'lens' | 'moment' | 'light' | 'glossy';
  index: number;
  count: number;
}

export interface DebugStep {
  kind: StepKind;
  line: PseudocodeLine;
  /** The ray highlighted in 3D: the one cast, or the hit being shaded or returned; null for a lens point and the average. */
  ray: RayNode | null;
  /** The surface ray whose hit the equation shows: the ray itself, or the hit a light or child ray leaves from. */
  hit: RayNode | null;
  /** The hit `ray` leaves from: its parent hit (null for a primary ray). */
  from: RayNode | null;
  /** Recursion depth of `ray` (primary rays 0; a shadow ray has its hit's depth). */
  depth: number;
  /** Which supersample's tree (0 … s²−1). */
  sample: number;
  /** How deep the step sits in the pixel's tree (sample → lens point → moment → hit → its rays): the tree view indents by it. */
  level: number;
  /** Its place among its siblings (sample 2 of 4, lens point 3 of 9, light sample 5 of 9…), or null when it has none. */
  place: StepPlace | null;
  /**
   * What one unit of `ray`'s colour counts for in the pixel: the product of the weights from
   * the pixel down to it (1/s², 1/(n²·k), ks, kr, kt, ks/m²). For a light ray: its hit's.
   */
  share: number;
  /** What this step adds to the pixel: share × the colour it adds (black where it adds nothing). */
  adds: Color;
  /** The pixel so far: the sum of every step's `adds` up to and including this one. */
  sum: Color;
}

/** A pixel's trace as the steps the tracer took, in its order (depth first, spec §2 of the debugger). */
export interface DebugProgram {
  trace: PixelTrace;
  steps: DebugStep[];
  /** For each step, the rays drawn by then (cast so far), as an index into `rays`: rays[0 … shownUpTo[i]). */
  shownUpTo: number[];
  /** Every ray in the order it is cast. */
  rays: RayNode[];
  /** For each ray, the step after which its colour is in its parent's (a light ray's own step, a child's return). */
  doneAt: Map<RayNode, number>;
}

/** Whether the object a ray hit is glass (transparent), from the scene, or from its terms when the scene no longer has it. */
function isGlass(node: RayNode, scene: Scene): boolean {
  const object = scene.objects.find((candidate) => candidate.id === node.objectId);
  return object ? object.material.transparent : node.terms?.refract != null;
}

const BLACK: Color = [0, 0, 0];

const times = (color: Color, factor: number): Color => [color[0] * factor, color[1] * factor, color[2] * factor];

/** Where each of `nodes` sits among those of the same key (1-based), when more than one shares it. */
function placesAmong(nodes: RayNode[], of: StepPlace['of'], key: (node: RayNode) => string | null): Map<RayNode, StepPlace> {
  const groups = new Map<string, RayNode[]>();
  for (const node of nodes) {
    const k = key(node);
    if (k !== null) groups.set(k, [...(groups.get(k) ?? []), node]);
  }
  const places = new Map<RayNode, StepPlace>();
  for (const group of groups.values()) if (group.length > 1) group.forEach((node, index) => places.set(node, { of, index: index + 1, count: group.length }));
  return places;
}

/**
 * The lens and time rays of a sample's root (distribution-effects §3: lens point by lens point,
 * each at its k moments), grouped by lens point.
 */
function byLensPoint(root: RayNode): RayNode[][] {
  const groups: RayNode[][] = [];
  for (const child of root.children) {
    const last = groups.at(-1);
    if (last && last[0].lensPoint?.every((value, i) => value === child.lensPoint?.[i])) last.push(child);
    else groups.push([child]);
  }
  return groups;
}

/**
 * The steps of a pixel's trace. Traced with terms (as the debugger does), each step also says
 * what it adds to the pixel, so the running sum ends at the pixel's colour: a hit adds its
 * ambient terms, each light ray its sample's diffuse and highlight, a missed ray the
 * background, each times its share; a return adds what clamping took away (a negative amount).
 */
export function debugProgram(trace: PixelTrace, scene: Scene): DebugProgram {
  const steps: DebugStep[] = [];
  const rays: RayNode[] = [];
  const shownUpTo: number[] = [];
  const doneAt = new Map<RayNode, number>();
  let sum: Color = [0, 0, 0];
  const push = (step: Omit<DebugStep, 'sum' | 'adds' | 'place'> & { adds?: Color; place?: StepPlace | null }, casts: boolean) => {
    const adds = step.adds ?? BLACK;
    sum = [sum[0] + adds[0], sum[1] + adds[1], sum[2] + adds[2]];
    if (casts && step.ray) rays.push(step.ray);
    steps.push({ ...step, adds, place: step.place ?? null, sum });
    shownUpTo.push(rays.length);
    return steps.length - 1;
  };

  /** A ray from `parent` (a hit, or null), with `share` of the pixel per unit of its colour. */
  const visit = (
    node: RayNode,
    parent: RayNode | null,
    share: number,
    depth: number,
    level: number,
    sample: number,
    line: PseudocodeLine,
    place: StepPlace | null,
  ) => {
    const from = parent;
    if (node.absorbed) {
      // A glossy direction into the surface: not traced, it adds black.
      doneAt.set(node, push({ kind: 'cast', line, ray: node, hit: parent, from, depth, level, sample, share, place }, true));
      return;
    }
    const before = sum;
    push({ kind: 'cast', line, ray: node, hit: parent, from, depth, level, sample, share, place }, true);
    if (!node.hit) {
      doneAt.set(
        node,
        push(
          { kind: 'return', line: 'nearest-hit', ray: node, hit: parent, from, depth, level: level + 1, sample, share, adds: times(node.color, share) },
          false,
        ),
      );
      return;
    }
    const terms = node.terms;
    const ambient = terms
      ? terms.lights.reduce<Color>((total, light) => [total[0] + light.ambient[0], total[1] + light.ambient[1], total[2] + light.ambient[2]], terms.ambient)
      : BLACK;
    const inner = level + 1;
    push({ kind: 'shade', line: 'ambient', ray: node, hit: node, from, depth, level: inner, sample, share, adds: times(ambient, share) }, false);
    const glass = isGlass(node, scene);
    const lightPlaces = placesAmong(node.children, 'light', (child) => child.lightId);
    const glossyPlaces = placesAmong(node.children, 'glossy', (child) => (child.glossy ? child.type : null));
    let split = false;
    for (const child of node.children) {
      if (child.type === 'reflect' || child.type === 'refract') {
        if (glass && !split) {
          push({ kind: 'split', line: 'schlick', ray: node, hit: node, from, depth, level: inner, sample, share }, false);
          split = true;
        }
        const childLine = child.glossy ? 'glossy' : glass ? 'glass' : 'mirror';
        visit(child, node, share * (child.weight ?? 0), depth + 1, inner, sample, childLine, glossyPlaces.get(child) ?? null);
      } else {
        const blocked = child.type === 'shadow' || child.type === 'area-shadow';
        const step = push(
          {
            kind: 'light',
            line: blocked ? 'blocked' : 'lit',
            ray: child,
            hit: node,
            from: node,
            depth,
            level: inner,
            sample,
            share,
            adds: times(child.color, share),
            place: lightPlaces.get(child),
          },
          true,
        );
        doneAt.set(child, step);
      }
    }
    // What clamping takes away; without terms (never in the debugger), whatever is left to reach share × the ray's colour.
    const adds: Color = terms
      ? times([0, 1, 2].map((c) => node.color[c] - terms.sum[c]) as Color, share)
      : ([0, 1, 2].map((c) => share * node.color[c] - (sum[c] - before[c])) as Color);
    doneAt.set(node, push({ kind: 'return', line: 'return', ray: node, hit: node, from, depth, level: inner, sample, share, adds }, false));
  };

  const samples = trace.rays.length;
  trace.rays.forEach((root, sample) => {
    const share = root.weight ?? 1 / samples;
    const samplePlace: StepPlace | null = samples > 1 ? { of: 'sample', index: sample + 1, count: samples } : null;
    const nested = root.children.length > 0 && root.children.every((child) => child.type === 'primary');
    if (!nested) {
      visit(root, null, share, 0, 0, sample, 'trace-primary', samplePlace);
      return;
    }
    // A sample of several rays: its pinhole ray to the point in focus, then each lens point's rays at their moments.
    push({ kind: 'sample', line: 'sample-loop', ray: root, hit: null, from: null, depth: 0, level: 0, sample, share, place: samplePlace }, true);
    const lensPoints = byLensPoint(root);
    const grouped = lensPoints.length > 1 && lensPoints.some((group) => group.length > 1);
    const raysPerSample = root.children.length;
    lensPoints.forEach((group, lens) => {
      const level = grouped ? 2 : 1;
      if (grouped)
        push(
          {
            kind: 'lens',
            line: 'lens-loop',
            ray: null,
            hit: null,
            from: null,
            depth: 0,
            level: 1,
            sample,
            share: share / lensPoints.length,
            place: { of: 'lens', index: lens + 1, count: lensPoints.length },
          },
          false,
        );
      group.forEach((child, index) => {
        const place: StepPlace =
          lensPoints.length === 1 || grouped
            ? { of: 'moment', index: index + 1, count: group.length }
            : { of: 'lens', index: lens + 1, count: lensPoints.length };
        visit(child, null, share * (child.weight ?? 1 / raysPerSample), 0, level, sample, 'trace-primary', place);
      });
    });
    doneAt.set(root, steps.length - 1);
  });
  push({ kind: 'average', line: 'average', ray: null, hit: null, from: null, depth: 0, level: 0, sample: samples - 1, share: 1 }, false);
  return { trace, steps, shownUpTo, rays, doneAt };
}

/**
 * What the ray of a light step stands for in the pixel: its hit's share, over n² for one
 * sample of an n×n area light (its colour carries I/n²); a merged cone stands for all of them.
 */
export function lightRayShare(step: DebugStep): number {
  const ray = step.ray;
  if (step.kind !== 'light' || !ray || ray.corners) return step.share;
  return step.share / lightSamples(step);
}

/** n²: how many samples the light of a light step's ray has (1 for a point or spot light). */
export function lightSamples(step: DebugStep): number {
  return step.hit?.terms?.lights.find((light) => light.lightId === step.ray?.lightId)?.samples ?? 1;
}

/** The step on which `ray` is cast (where clicking a term jumps the highlight to), or −1. */
export function stepCasting(program: DebugProgram, ray: RayNode): number {
  return program.steps.findIndex((step) => (step.kind === 'cast' || step.kind === 'light' || step.kind === 'sample') && step.ray === ray);
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
