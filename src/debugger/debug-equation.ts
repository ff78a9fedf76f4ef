import type { DebuggerTerm } from '../lab-state/lab-action.ts';
import type { Color, Scene } from '../scene/scene.ts';
import type { RayNode } from '../tracer/ray-tree.ts';

/** The kinds of term a hit's colour is the sum of (ray-debugger spec §2, the equation panel). */
export type TermKind = DebuggerTerm;

/** One number or colour of a term, by its symbol in the shading model (scene-and-tracer spec §2). */
export interface Factor {
  /** e.g. "ka", "C", "I", "A", "S", "N·L", "(R·V)ⁿ", "kd", "ld", "Lc", "w". */
  symbol: string;
  value: number | Color;
}

export interface EquationTerm {
  /** Unique within the equation: "ambient", "sun:diffuse", "reflect"… */
  id: string;
  kind: TermKind;
  /** The light it comes from (light terms), else null. */
  lightId: string | null;
  /** What it adds to the colour. */
  color: Color;
  /** The factors it is the product of (for an area light: the means over its samples). */
  factors: Factor[];
  /** Area light: its n² samples' terms are summed (so the factors are means, not exact). */
  samples: number;
  /** The ray that produced it (a shadow ray toward its light, the reflected or refracted child), or null (ambient terms). */
  ray: RayNode | null;
}

/** A hit's colour written out: the sum of its terms, clamped. */
export interface Equation {
  hit: RayNode;
  terms: EquationTerm[];
  /** The terms added up (before clamping). */
  sum: Color;
  /** What the ray returns: sum clamped to 0..1 per channel. */
  color: Color;
  /** Whether clamping changed any channel. */
  clamped: boolean;
}

const scaled = (color: Color, factor: number): Color => [color[0] * factor, color[1] * factor, color[2] * factor];

/**
 * The equation of a hit traced with terms, with the material's and lights' numbers from
 * the scene (factors whose object or light the scene no longer has are left out). Null
 * when the ray has no terms (it missed, or was traced without them).
 */
export function equationOf(hit: RayNode, scene: Scene): Equation | null {
  const terms = hit.terms;
  if (!terms) return null;
  const material = scene.objects.find((object) => object.id === hit.objectId)?.material;
  const list: EquationTerm[] = [];
  const add = (term: Omit<EquationTerm, 'samples'> & { samples?: number }) => list.push({ samples: 1, ...term });

  add({ id: 'ambient', kind: 'ambient', lightId: null, color: terms.ambient, ray: null, factors: material ? [{ symbol: 'ka', value: material.ambient }, { symbol: 'C', value: material.color }] : [] });
  for (const lightTerms of terms.lights) {
    const light = scene.lights.find((candidate) => candidate.id === lightTerms.lightId);
    const id = lightTerms.lightId;
    // The ray this light's terms came from: its first shadow ray that reached the light (or, with
    // Shadows off, its untested direction), else its first blocked one.
    const rays = hit.children.filter((child) => child.lightId === id);
    const ray = rays.find((child) => child.type === 'light' || child.type === 'area-light') ?? rays[0] ?? null;
    const shared: Factor[] = [
      ...(light ? [{ symbol: 'I', value: light.intensity }] : []),
      { symbol: 'A', value: lightTerms.attenuation },
      { symbol: 'S', value: lightTerms.visibility },
    ];
    const samples = lightTerms.samples;
    add({ id: `${id}:ambient`, kind: 'light-ambient', lightId: id, color: lightTerms.ambient, ray: null,
      factors: light && material ? [{ symbol: 'la', value: light.ambient }, { symbol: 'Lc', value: light.color }, { symbol: 'C', value: material.color }] : [] });
    add({ id: `${id}:diffuse`, kind: 'diffuse', lightId: id, color: lightTerms.diffuse, ray, samples,
      factors: [...shared, { symbol: 'N·L', value: lightTerms.NdotL }, ...(material && light ? [{ symbol: 'kd', value: material.diffuse }, { symbol: 'ld', value: light.diffuse }, { symbol: 'Lc', value: light.color }, { symbol: 'C', value: material.color }] : [])] });
    add({ id: `${id}:specular`, kind: 'specular', lightId: id, color: lightTerms.specular, ray, samples,
      factors: [...shared, { symbol: 'R·V', value: lightTerms.RdotV }, ...(material && light ? [{ symbol: 'n', value: material.shininess }, { symbol: 'ks', value: material.specular }, { symbol: 'ls', value: light.specular }, { symbol: 'Lc', value: light.color }] : [])] });
  }
  // In the tracer's order: glass traces its refracted ray first.
  for (const kind of ['refract', 'reflect'] as const) {
    const child = terms[kind];
    if (!child) continue;
    const ray = hit.children.find((candidate) => candidate.type === kind) ?? null;
    add({ id: kind, kind, lightId: null, color: scaled(child.color, child.weight), ray, factors: [{ symbol: 'w', value: child.weight }, { symbol: 'colour', value: child.color }] });
  }
  const clamped = terms.sum.some((value, c) => value !== hit.color[c]);
  return { hit, terms: list, sum: terms.sum, color: hit.color, clamped };
}

/** The pixel as the mean of its samples' colours (the last step): each sample weighs 1/s². */
export interface PixelAverage {
  samples: Color[];
  /** The pixel's colour, as the image has it (32-bit floats). */
  color: Color;
}

export function pixelAverage(roots: RayNode[], color: Color): PixelAverage {
  return { samples: roots.map((root) => root.color), color };
}

/** An 8-bit channel as the image stores it: round(clamp(c)·255) (scene-and-tracer spec §2). */
export function toByte(value: number): number {
  return Math.round(Math.min(1, Math.max(0, value)) * 255);
}
