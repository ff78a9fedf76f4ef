/**
 * Which angle Schlick's approximation takes at glass. The exact Fresnel equations (pbrt-v4's
 * FrDielectric evaluates them) give the same reflectance seen from either side of a surface,
 * as they are symmetric in θi and θt; Schlick's R0 + (1 − R0)(1 − cos θ)⁵ follows them only
 * with θ on the side of the lower index. So the incident angle entering glass and the
 * transmitted angle leaving it: `c = t·n` for a ray leaving the glass in Shirley &
 * Marschner, "Fundamentals of Computer Graphics" §13.1. With the angle inside the glass, a
 * ray leaving it reflects about R0 up to the critical angle instead of rising towards 1.
 * ("Ray Tracing in One Weekend" takes the incident angle on both sides, a simplification.)
 */
import { describe, expect, it } from 'vitest';
import { schlickReflectance } from '../../src/tracer/fresnel.ts';
import type { RayNode } from '../../src/tracer/ray-tree.ts';
import { tracePixel } from '../../src/tracer/trace-pixel.ts';
import { matte, tracerSceneFrom } from '../support/test-scene.ts';

const IOR = 1.5;
/** A ball of radius 1 (the unit sphere has radius 0.5) at the origin. */
const glassBall = { id: 'glass', shape: 'sphere', scale: [2, 2, 2], material: matte([1, 1, 1], { transparent: true, diffuse: 0, refractiveIndex: IOR }) };

/** The first hit of the ray from `position` to `target` (a one-pixel screen's ray), traced with its weights. */
function firstHit(position: number[], target: number[]): RayNode {
  const scene = tracerSceneFrom({
    camera: { position, target, pixels: [1, 1] },
    settings: { background: [1, 1, 1], supersampling: 1, maxDepth: 1 },
    objects: [glassBall],
    lights: [],
  });
  const root = tracePixel(scene, 0, 0, 0, { terms: true }).rays[0];
  expect(root).toMatchObject({ type: 'primary', hit: true, objectId: 'glass' });
  return root;
}

const dot = (a: number[], b: number[]) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const weightOf = (node: RayNode, type: 'reflect' | 'refract') => node.children.find((c) => c.type === type)!.weight!;

/** cos θi and cos θt of a ray through a surface (normal facing the ray) by Snell's law, η = n₁/n₂. */
function cosines(hit: RayNode, eta: number): { cosI: number; cosT: number } {
  const cosI = -dot(hit.direction, hit.normal!);
  const sinT = eta * Math.sqrt(1 - cosI * cosI);
  return { cosI, cosT: Math.sqrt(1 - sinT * sinT) };
}

describe("Schlick's angle is the one on the side of the lower index", () => {
  it('leaving glass: kr = Schlick(cos θt), the transmitted angle outside', () => {
    // From inside the ball, 0.6 m above its centre, looking sideways: 37° to the normal
    // (cos θi = 0.8), below the critical angle of 41.8°.
    const hit = firstHit([0, 0.6, 0], [1, 0.6, 0]);
    const { cosI, cosT } = cosines(hit, IOR);
    expect(cosI).toBeCloseTo(0.8, 6);
    // The two angles give clearly different answers here, so the test tells them apart.
    expect(schlickReflectance(cosT, IOR) - schlickReflectance(cosI, IOR)).toBeGreaterThan(0.02);

    expect(weightOf(hit, 'reflect')).toBeCloseTo(schlickReflectance(cosT, IOR), 12);
    expect(weightOf(hit, 'refract')).toBeCloseTo(1 - schlickReflectance(cosT, IOR), 12);
  });

  it('entering glass: kr = Schlick(cos θi), the incident angle outside', () => {
    // From outside, 0.9 m above the centre: a slanted hit, 64° to the normal (cos θi = 0.436).
    const hit = firstHit([0, 0.9, 4], [0, 0.9, 0]);
    const { cosI, cosT } = cosines(hit, 1 / IOR);
    expect(cosI).toBeCloseTo(Math.sqrt(1 - 0.81), 6);
    expect(schlickReflectance(cosI, IOR) - schlickReflectance(cosT, IOR)).toBeGreaterThan(0.02);

    expect(weightOf(hit, 'reflect')).toBeCloseTo(schlickReflectance(cosI, IOR), 12);
    expect(weightOf(hit, 'refract')).toBeCloseTo(1 - schlickReflectance(cosI, IOR), 12);
  });
});
