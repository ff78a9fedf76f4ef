import { Vector3 } from 'three';
import { reflect } from '../../tracer/fresnel.ts';
import { phongPower } from '../../tracer/phong-power.ts';
import { RandomStream } from '../../tracer/sampler.ts';
import type { CaseDrawing } from './case-drawing.ts';
import type { LabCase, Rgb, Tolerance, Vec3 } from './code-lab-grading.ts';
import { dot, randomDirection, scaled, unit, v } from './lab-vectors.ts';
import type { PhongEdge } from './phong-edges.ts';

/**
 * The Phong lab: what one point light adds where a ray hits, diffuse (Lambert) plus
 * highlight (Phong), as the tracer's Whitted integrator adds it (addDirectLight in
 * src/tracer/whitted-integrator.ts; Shirley & Marschner, "Fundamentals of Computer
 * Graphics", 4th ed., §4.5 and §10.2.1, with Phong's R·V instead of Blinn's N·H):
 *   L = (light − point)/|light − point|, R = 2(N·L)N − L,
 *   colour = I·Lc·( kd·max(N·L, 0)·C + ks·max(R·V, 0)ⁿ ), and 0 when N·L ≤ 0.
 * The lab's light has A = 1 (no distance or angle attenuation), S = 1 (nothing in the way)
 * and its own diffuse and specular factors ld = ls = 1, as level 03's lamp.
 * The reference is built from the tracer's own pieces (reflect, phongPower) in the tracer's
 * order of operations; the hot loop itself stays inlined (docs/performance.md, "Inlining
 * budget"), and tests/quest/code-lab-phong.test.ts pins this function to the terms the tracer
 * records for real hits.
 */

/** The lab's point light: where it is, its colour Lc and its intensity I. */
export interface PhongLight {
  position: Vec3;
  color: Rgb;
  intensity: number;
}

/** The lab's material: colour C, kd (**Diffuse**), ks (**Specular**) and the shininess n. */
export interface PhongMaterial {
  color: Rgb;
  diffuse: number;
  specular: number;
  shininess: number;
}

/**
 * Colours of a size about 1: 1e-9 of the brightest channel is far below an 8-bit pixel's
 * step and far above the rounding of any way of writing the formula (pow included).
 */
export const PHONG_TOLERANCE: Tolerance = { answer: 'colour', relative: 1e-9 };

const white: Rgb = { r: 1, g: 1, b: 1 };
const orange: Rgb = { r: 0.95, g: 0.45, b: 0.1 };
const ball: PhongMaterial = { color: orange, diffuse: 1, specular: 0.5, shininess: 10 };
const up = v(0, 1, 0);

/** Each edge case: point, unit normal N, unit V toward the eye (N·V > 0, as the tracer turns N), light, material. */
const EDGE_CASES: Record<PhongEdge, [Vec3, Vec3, Vec3, PhongLight, PhongMaterial]> = {
  // The lamp under the floor: N·L < 0, so no light at all (not a negative one).
  'phong-light-behind': [v(0, 0, 0), up, unit(v(1, 1, 0)), { position: v(-1, -2, 0), color: white, intensity: 1 }, ball],
  // The eye exactly where the lamp mirrors (V = R): R·V = 1, the brightest highlight.
  'phong-in-the-highlight': [v(0, 0, 0), up, unit(v(1, 1, 0)), { position: v(-2, 2, 0), color: white, intensity: 1 }, ball],
  // The eye 20° beside the mirror direction: a highlight of cos(20°)ⁿ.
  'phong-beside-the-highlight': [
    v(0, 0, 0),
    up,
    v(Math.sin((65 * Math.PI) / 180), Math.cos((65 * Math.PI) / 180), 0),
    { position: v(-3, 3, 0), color: white, intensity: 1 },
    ball,
  ],
  // A blue-green lamp of intensity 2 on a tilted, off-centre surface: Lc, I and C each count.
  'phong-coloured-light': [
    v(1, 0.5, -2),
    unit(v(1, 2, 2)),
    unit(v(0, 1, 1)),
    { position: v(3, 4, 0), color: { r: 0.2, g: 0.8, b: 1 }, intensity: 2 },
    { color: { r: 0.3, g: 0.9, b: 0.5 }, diffuse: 0.8, specular: 0.7, shininess: 5 },
  ],
};

const reusable = { l: new Vector3(), n: new Vector3(), r: new Vector3() };

/** The tracer's answer for one point light (A = S = ld = ls = 1), term by term as addDirectLight computes it. */
export function tracerPhong(point: Vec3, normal: Vec3, toEye: Vec3, light: PhongLight, material: PhongMaterial): Rgb {
  const l = reusable.l.set(light.position.x - point.x, light.position.y - point.y, light.position.z - point.z).normalize();
  const n = reusable.n.set(normal.x, normal.y, normal.z);
  const nDotL = n.dot(l);
  // A light behind the surface adds nothing: no diffuse and no highlight.
  if (nDotL <= 0) return { r: 0, g: 0, b: 0 };
  // R = 2(N·L)N − L: the tracer's reflect of −L about N.
  const r = reflect(l.negate(), n, reusable.r);
  const rDotV = r.x * toEye.x + r.y * toEye.y + r.z * toEye.z;
  const highlight = material.specular > 0 ? phongPower(Math.max(rDotV, 0), material.shininess) * material.specular : 0;
  const diffuse = nDotL * material.diffuse;
  const k = light.intensity;
  const channel = (lc: number, c: number) => k * lc * (diffuse * c) + k * lc * highlight;
  return { r: channel(light.color.r, material.color.r), g: channel(light.color.g, material.color.g), b: channel(light.color.b, material.color.b) };
}

const randomColour = (random: RandomStream): Rgb => ({ r: random.next(), g: random.next(), b: random.next() });

/** One random case: N any direction, V on N's side, the light 1 to 5 away in any direction (so behind the surface half the time). */
function randomCase(random: RandomStream): LabCase {
  const point = v(4 * random.next() - 2, 4 * random.next() - 2, 4 * random.next() - 2);
  const normal = randomDirection(random);
  const drawn = randomDirection(random);
  const toEye = dot(drawn, normal) < 0 ? scaled(drawn, -1) : drawn;
  const away = scaled(randomDirection(random), 1 + 4 * random.next());
  const light: PhongLight = {
    position: v(point.x + away.x, point.y + away.y, point.z + away.z),
    color: randomColour(random),
    intensity: 0.5 + 1.5 * random.next(),
  };
  const material: PhongMaterial = {
    color: randomColour(random),
    diffuse: random.next(),
    specular: random.next(),
    shininess: 1 + Math.floor(100 * random.next()),
  };
  const args = [point, normal, toEye, light, material] as const;
  return { kind: 'random', args: [...args], expected: tracerPhong(...args) };
}

/** The lab's cases: the named edge cases first, then `count` seeded random ones. */
export function phongCases(edges: readonly PhongEdge[], count: number, seed: number): LabCase[] {
  const random = new RandomStream().reset(seed);
  const named = edges.map((kind): LabCase => ({ kind, args: EDGE_CASES[kind], expected: tracerPhong(...EDGE_CASES[kind]) }));
  return [...named, ...Array.from({ length: count }, () => randomCase(random))];
}

const plus = (a: Vec3, b: Vec3, s = 1): Vec3 => v(a.x + s * b.x, a.y + s * b.y, a.z + s * b.z);
const cross = (a: Vec3, b: Vec3): Vec3 => v(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
const size = (a: Vec3) => Math.hypot(a.x, a.y, a.z);

/** Whether the case's light is behind the surface (N·L ≤ 0): then it adds nothing, however the rest is computed. */
export function lightBehindSurface(labCase: LabCase): boolean {
  const [point, normal, , light] = labCase.args as [Vec3, Vec3, Vec3, PhongLight];
  return dot(normal, plus(light.position, point, -1)) <= 0;
}

/**
 * How a Phong case looks in 3D: the shading point on a square piece of its surface, and from
 * it the normal N, L toward the light, V toward the eye and the mirror direction R = 2(N·L)N − L
 * (Shirley & Marschner §10.2.1), all of one length, half the way to the light, each with its
 * letter; the light itself at its place. A light behind the surface shows as L pointing below
 * the square. The answers are colours, not places: the panel's legend shows them. Seen from
 * the side of the plane of N and L, a little above the surface, where the angles read truest.
 */
export function drawPhongCase(labCase: LabCase): CaseDrawing {
  const [point, normal, toEye, light] = labCase.args as [Vec3, Vec3, Vec3, PhongLight];
  const toLight = plus(light.position, point, -1);
  const reach = size(toLight) / 2;
  const l = unit(toLight);
  const mirror = plus(scaled(normal, 2 * dot(normal, l)), l, -1);
  const arrow = (direction: Vec3, mark: 'normal' | 'light' | 'eye' | 'mirror', label: string) => ({
    from: point,
    to: plus(point, direction, reach),
    mark,
    arrow: true,
    label,
  });
  // Two directions in the surface: any one across N, and N × that one.
  const across = unit(cross(normal, Math.abs(normal.x) < 0.9 ? v(1, 0, 0) : v(0, 1, 0)));
  const along = cross(normal, across);
  const corner = (a: number, b: number) => plus(plus(point, across, a * reach), along, b * reach);
  const side = cross(normal, l);
  const flat = size(side) > 1e-3 ? unit(side) : across;
  const facing = dot(flat, toEye) < 0 ? scaled(flat, -1) : flat;
  return {
    segments: [arrow(normal, 'normal', 'N'), arrow(l, 'light', 'L'), arrow(toEye, 'eye', 'V'), arrow(mirror, 'mirror', 'R')],
    points: [
      { at: point, mark: 'surface' },
      { at: light.position, mark: 'light' },
    ],
    shapes: [{ kind: 'quad', corners: [corner(-1, -1), corner(1, -1), corner(1, 1), corner(-1, 1)], fill: 'surface' }],
    lookFrom: unit(plus(facing, normal, 0.35)),
  };
}
