import type { DebuggerTerm } from '../lab-state/lab-action.ts';
import type { Color, Scene } from '../scene/scene.ts';
import type { RayNode } from '../tracer/ray-tree.ts';
import { stepCasting, type DebugProgram, type StepPlace } from './debug-steps.ts';

/** The kinds of term a hit's colour is the sum of (ray-debugger spec §2, the equation panel). */
export type TermKind = DebuggerTerm;

/** One number or colour of a term, by its symbol in the shading model (scene-and-tracer spec §2). */
export interface Factor {
  /** e.g. "ka", "C", "I", "A", "S", "N·L", "(R·V)ⁿ", "kd", "ld", "Lc", "w", "trace" (a child ray's colour). */
  symbol: string;
  value: number | Color;
}

export interface EquationTerm {
  /** Unique within the equation: "ambient", "sun:diffuse", "reflect"… */
  id: string;
  kind: TermKind;
  /** The light it comes from (light terms), else null. */
  lightId: string | null;
  /** What it adds to the colour (so far, in an equation stepped through). */
  color: Color;
  /** The factors it is the product of (for an area light: the means over its samples). */
  factors: Factor[];
  /** Area light: its n² samples' terms are summed (so the factors are means, not exact). */
  samples: number;
  /** The ray that produced it (a shadow ray toward its light, the reflected or refracted child), or null (ambient terms). */
  ray: RayNode | null;
  /** The rays it is made of (a light's shadow rays, a rough surface's spread rays), and how many are added so far. */
  rays: { added: number; total: number };
}

/** A hit's colour written out: the sum of its terms, clamped. */
export interface Equation {
  hit: RayNode;
  terms: EquationTerm[];
  /** The terms added up (before clamping), so far. */
  sum: Color;
  /** What the ray returns: the full sum clamped to 0..1 per channel. */
  color: Color;
  /** Whether clamping changed any channel. */
  clamped: boolean;
  /** Whether every term's rays are added (always, unless the equation is being stepped through). */
  complete: boolean;
}

const scaled = (color: Color, factor: number): Color => [color[0] * factor, color[1] * factor, color[2] * factor];
const plus = (a: Color, b: Color): Color => [a[0] + b[0], a[1] + b[1], a[2] + b[2]];

/**
 * The equation of a hit traced with terms, with the material's and lights' numbers from
 * the scene (factors whose object or light the scene no longer has are left out). Null
 * when the ray has no terms (it missed, or was traced without them).
 *
 * `added` says which of the hit's rays are added so far (the debugger's cursor): a light's
 * terms then hold the parts of its shadow rays added so far, sample by sample, and a
 * reflected or refracted term its rays that have returned. Without it every ray is added,
 * and the sum is the tracer's, bit for bit.
 */
export function equationOf(hit: RayNode, scene: Scene, added?: (ray: RayNode) => boolean): Equation | null {
  const terms = hit.terms;
  if (!terms) return null;
  const isAdded = added ?? (() => true);
  const material = scene.objects.find((object) => object.id === hit.objectId)?.material;
  const list: EquationTerm[] = [];
  const add = (term: Omit<EquationTerm, 'samples' | 'rays'> & { samples?: number; rays?: EquationTerm['rays'] }) =>
    list.push({ samples: 1, rays: { added: 0, total: 0 }, ...term });

  add({
    id: 'ambient',
    kind: 'ambient',
    lightId: null,
    color: terms.ambient,
    ray: null,
    factors: material
      ? [
          { symbol: 'ka', value: material.ambient },
          { symbol: 'C', value: material.color },
        ]
      : [],
  });
  for (const lightTerms of terms.lights) {
    const light = scene.lights.find((candidate) => candidate.id === lightTerms.lightId);
    const id = lightTerms.lightId;
    // The ray this light's terms came from: its first shadow ray that reached the light (or, with
    // Shadows off, its untested direction), else its first blocked one.
    const rays = hit.children.filter((child) => child.lightId === id);
    const ray = rays.find((child) => child.type === 'light' || child.type === 'area-light') ?? rays[0] ?? null;
    const done = rays.filter(isAdded);
    const progress = { added: done.length, total: rays.length };
    const partSum = (part: 'diffuse' | 'specular'): Color =>
      added ? done.reduce<Color>((sum, child) => (child.parts ? plus(sum, child.parts[part]) : sum), [0, 0, 0]) : lightTerms[part];
    const shared: Factor[] = [
      ...(light ? [{ symbol: 'I', value: light.intensity }] : []),
      { symbol: 'A', value: lightTerms.attenuation },
      { symbol: 'S', value: lightTerms.visibility },
    ];
    const samples = lightTerms.samples;
    add({
      id: `${id}:ambient`,
      kind: 'light-ambient',
      lightId: id,
      color: lightTerms.ambient,
      ray: null,
      factors:
        light && material
          ? [
              { symbol: 'la', value: light.ambient },
              { symbol: 'Lc', value: light.color },
              { symbol: 'C', value: material.color },
            ]
          : [],
    });
    add({
      id: `${id}:diffuse`,
      kind: 'diffuse',
      lightId: id,
      color: partSum('diffuse'),
      ray,
      samples,
      rays: progress,
      factors: [
        ...shared,
        { symbol: 'N·L', value: lightTerms.NdotL },
        ...(material && light
          ? [
              { symbol: 'kd', value: material.diffuse },
              { symbol: 'ld', value: light.diffuse },
              { symbol: 'Lc', value: light.color },
              { symbol: 'C', value: material.color },
            ]
          : []),
      ],
    });
    add({
      id: `${id}:specular`,
      kind: 'specular',
      lightId: id,
      color: partSum('specular'),
      ray,
      samples,
      rays: progress,
      factors: [
        ...shared,
        { symbol: 'R·V', value: lightTerms.RdotV },
        ...(material && light
          ? [
              { symbol: 'n', value: material.shininess },
              { symbol: 'ks', value: material.specular },
              { symbol: 'ls', value: light.specular },
              { symbol: 'Lc', value: light.color },
            ]
          : []),
      ],
    });
  }
  // In the tracer's order: glass traces its refracted ray first.
  for (const kind of ['refract', 'reflect'] as const) {
    const child = terms[kind];
    if (!child) continue;
    const rays = hit.children.filter((candidate) => candidate.type === kind);
    const done = rays.filter(isAdded);
    const ray = rays.find((candidate) => !candidate.absorbed) ?? null;
    // A rough surface's spread rays add weight/m² × their colour each (an absorbed one adds black).
    const color = added ? done.reduce<Color>((sum, one) => plus(sum, scaled(one.color, one.weight ?? 0)), [0, 0, 0]) : scaled(child.color, child.weight);
    add({
      id: kind,
      kind,
      lightId: null,
      color,
      ray,
      rays: { added: done.length, total: rays.length },
      factors: [
        { symbol: 'w', value: child.weight },
        { symbol: 'trace', value: child.color },
      ],
    });
  }
  const complete = list.every((term) => term.rays.added === term.rays.total);
  const sum = added ? list.reduce<Color>((total, term) => plus(total, term.color), [0, 0, 0]) : terms.sum;
  const clamped = terms.sum.some((value, c) => value !== hit.color[c]);
  return { hit, terms: list, sum, color: hit.color, clamped, complete };
}

/** The equation of the hit the cursor is at, with the rays added by step `index` (its terms grow as the debugger steps). */
export function equationAt(program: DebugProgram, index: number, scene: Scene): Equation | null {
  const hit = program.steps[index]?.hit;
  if (!hit) return null;
  return equationOf(hit, scene, (ray) => (program.doneAt.get(ray) ?? Infinity) <= index);
}

/** One of the colours the pixel adds up: a sample, or one lens or time ray of a pixel's only sample. */
export interface PixelPart {
  ray: RayNode;
  place: StepPlace | null;
  /** Its share of the pixel (1/s², 1/(n²·k), or both). */
  share: number;
}

/** The pixel as its parts' colours times their shares (the last step). */
export interface PixelAverage {
  parts: PixelPart[];
  /** How many primary rays the pixel casts (s²·n²·k). */
  rays: number;
  /** The pixel's colour, as the image has it (32-bit floats). */
  color: Color;
}

export function pixelAverage(program: DebugProgram): PixelAverage {
  const roots = program.trace.rays;
  const only = roots.length === 1 ? roots[0] : null;
  const nested = (root: RayNode) => root.children.length > 0 && root.children.every((child) => child.type === 'primary');
  const rays = only && nested(only) ? only.children : roots;
  const parts = rays.map((ray) => {
    const step = program.steps[stepCasting(program, ray)];
    return { ray, place: step?.place ?? null, share: step?.share ?? 0 };
  });
  const count = roots.reduce((total, root) => total + (nested(root) ? root.children.length : 1), 0);
  return { parts, rays: count, color: program.trace.color };
}

/** An 8-bit channel as the image stores it without gamma or dithering: round(clamp(c)·255) (scene-and-tracer spec §2). */
export function toByte(value: number): number {
  return Math.round(Math.min(1, Math.max(0, value)) * 255);
}
