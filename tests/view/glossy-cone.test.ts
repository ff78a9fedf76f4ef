import { describe, expect, it } from 'vitest';
import { DEFAULT_RAY_VIEW, type RayViewOptions } from '../../src/lab-state/lab-state.ts';
import type { Vec3 } from '../../src/scene/scene.ts';
import type { RayNode } from '../../src/tracer/ray-tree.ts';
import { GLOSSY_CONE_RAYS } from '../../src/view/glossy-cone.ts';
import { RAY_COLOR_KEYS } from '../../src/view/ray-palette.ts';
import { type SegmentList, visibleRays } from '../../src/view/ray-visibility.ts';
import { ray, screen } from '../support/ray-fixtures.ts';

const options = (changes: Partial<RayViewOptions> = {}): RayViewOptions => ({ ...DEFAULT_RAY_VIEW, ...changes });

const HIT: Vec3 = [0, 0, 0];

/**
 * m × m glossy reflections from the origin, spread up to `spread` around +Y on a grid, each
 * `length` long with a light ray from where it lands; `objectOf(k)` says what ray k hits.
 */
function fan(m: number, spread = 0.3, objectOf: (k: number) => string | null = () => 'board', length = (k: number) => 2 + (k % 3) * 0.1): RayNode[] {
  return Array.from({ length: m * m }, (_, k) => {
    const a = ((k % m) / (m - 1) - 0.5) * 2 * spread;
    const b = (Math.floor(k / m) / (m - 1) - 0.5) * 2 * spread;
    const n = Math.hypot(a, 1, b);
    const direction: Vec3 = [a / n, 1 / n, b / n];
    const objectId = objectOf(k);
    const end = direction.map((c) => c * length(k)) as Vec3;
    return ray('reflect', {
      origin: HIT,
      direction,
      length: objectId ? length(k) : 10,
      hit: objectId !== null,
      objectId,
      glossy: true,
      contribution: 0.01,
      color: [0.2, 0.3, k / (m * m)],
      children: objectId ? [ray('light', { origin: end, direction: [0, 0, 1], length: 1, contribution: 0.004 })] : [],
    });
  });
}

/** A primary ray 4 m long whose hit casts `children`. */
const pixelWith = (children: RayNode[]) =>
  screen(1, 1, () => [ray('primary', { direction: [0, -1, 0], origin: [0, 4, 0], length: 4, objectId: 'floor', children })]);

const types = (list: SegmentList) => list.nodes.slice(0, list.count).map((node) => node.type);

/** Where unit direction d crosses the cone's base plane, in the base's own coordinates (−1..1 inside). */
function onBase(list: SegmentList, i: number, d: Vec3): [number, number] {
  const c = [...list.corners.subarray(i * 12, i * 12 + 12)];
  const corner = (k: number) => c.slice(k * 3, k * 3 + 3);
  const centre = [0, 1, 2].map((axis) => (corner(0)[axis] + corner(1)[axis] + corner(2)[axis] + corner(3)[axis]) / 4);
  const u = [0, 1, 2].map((axis) => (corner(1)[axis] - corner(0)[axis]) / 2);
  const v = [0, 1, 2].map((axis) => (corner(3)[axis] - corner(0)[axis]) / 2);
  const apex = [...list.origin.subarray(i * 3, i * 3 + 3)];
  const normal = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
  const dotN = (p: number[]) => p[0] * normal[0] + p[1] * normal[1] + p[2] * normal[2];
  const t = dotN(centre.map((x, axis) => x - apex[axis])) / dotN(d);
  const offset = d.map((x, axis) => apex[axis] + x * t - centre[axis]);
  const dot = (p: number[], q: number[]) => p[0] * q[0] + p[1] * q[1] + p[2] * q[2];
  return [dot(offset, u) / dot(u, u), dot(offset, v) / dot(v, v)];
}

describe('a glossy fan drawn as one cone (distribution-effects §4)', () => {
  it('draws a fan of 36 rays that all hit the board as one cone, and the light rays they cast still as rays', () => {
    const rays = fan(6);
    const drawn = visibleRays(pixelWith(rays), options(), null);
    expect(drawn.cones.count).toBe(1);
    expect(types(drawn.cones)).toEqual(['reflect']);
    expect(RAY_COLOR_KEYS[drawn.cones.colorKey[0]]).toBe('reflect');
    expect(types(drawn.rays)).toEqual(['primary', ...Array(36).fill('light')]);
    const cone = drawn.cones.nodes[0];
    expect(cone).toMatchObject({ glossy: true, objectId: 'board', hit: true });
    expect(cone.contribution).toBeCloseTo(36 * 0.01, 12);
    expect(cone.children).toEqual(rays);
    // Apex at the hit, and it starts growing when the primary ray has arrived.
    expect([...drawn.cones.origin.subarray(0, 3)]).toEqual(HIT);
    expect(drawn.cones.start[0]).toBe(4);
    // Each light ray starts growing when its own glossy ray has arrived.
    expect([...drawn.rays.start.subarray(1, 37)]).toEqual(rays.map((r) => Math.fround(4 + r.length)));
  });

  it("has a base across the fan that every one of its rays passes through, at the fan's mean depth", () => {
    const rays = fan(6, 0.4);
    const drawn = visibleRays(pixelWith(rays), options(), null);
    for (const r of rays) {
      const [u, v] = onBase(drawn.cones, 0, r.direction);
      expect(Math.abs(u)).toBeLessThanOrEqual(1 + 1e-5);
      expect(Math.abs(v)).toBeLessThanOrEqual(1 + 1e-5);
    }
    // The outermost rays touch the edges: the base is no larger than the fan.
    expect(Math.max(...rays.map((r) => Math.abs(onBase(drawn.cones, 0, r.direction)[0])))).toBeCloseTo(1, 4);
    const meanDepth = rays.reduce((sum, r) => sum + r.direction[1] * r.length, 0) / rays.length;
    expect(drawn.cones.length[0] * drawn.cones.direction[1]).toBeCloseTo(meanDepth, 4);
  });

  it(`keeps a fan of ${GLOSSY_CONE_RAYS} rays, or one whose rays hit different things, as single rays`, () => {
    expect(GLOSSY_CONE_RAYS).toBe(25);
    const five = visibleRays(pixelWith(fan(5)), options(), null);
    expect(five.cones.count).toBe(0);
    expect(types(five.rays).filter((type) => type === 'reflect')).toHaveLength(25);
    const mixed = visibleRays(pixelWith(fan(6, 0.3, (k) => (k === 7 ? 'ball' : 'board'))), options(), null);
    expect(mixed.cones.count).toBe(0);
    const missing = visibleRays(pixelWith(fan(6, 0.3, (k) => (k === 0 ? null : 'board'))), options(), null);
    expect(missing.cones.count).toBe(0);
    expect(types(missing.rays).filter((type) => type === 'reflect')).toHaveLength(36);
  });

  it('does not count directions absorbed by the surface against the cone, and leaves them as they are', () => {
    const rays = fan(6);
    for (const k of [0, 1, 2, 3]) Object.assign(rays[k], { absorbed: true, length: 0, color: [0, 0, 0], children: [] });
    const drawn = visibleRays(pixelWith(rays), options(), null);
    expect(drawn.cones.count).toBe(1);
    expect(drawn.cones.nodes[0].children).toHaveLength(32);
    expect(drawn.rays.nodes.filter((node) => node.absorbed)).toHaveLength(4);
  });

  it("makes one cone per kind: a rough glass's reflected and refracted fans", () => {
    const refracted = fan(6).map((r) => ({ ...r, type: 'refract' as const, objectId: 'glass' }));
    const drawn = visibleRays(pixelWith([...fan(6), ...refracted]), options(), null);
    expect(types(drawn.cones)).toEqual(['reflect', 'refract']);
    expect(drawn.cones.nodes.map((node) => node.objectId)).toEqual(['board', 'glass']);
  });

  it("follows the panel's rules: a negligible cone goes with the rays under it", () => {
    const drawn = visibleRays(pixelWith(fan(6)), options({ hideNegligible: true, negligibleThreshold: 0.5 }), null);
    expect(drawn.cones.count).toBe(0);
    expect(types(drawn.rays)).toEqual(['primary']);
    // The fan's summed share (0.36) counts, not one ray's (0.01).
    expect(visibleRays(pixelWith(fan(6)), options({ hideNegligible: true, negligibleThreshold: 0.1 }), null).cones.count).toBe(1);
  });

  it('draws every glossy ray for the ray debugger, which steps through each one', () => {
    const drawn = visibleRays(pixelWith(fan(6)), options(), null, undefined, undefined, false);
    expect(drawn.cones.count).toBe(0);
    expect(types(drawn.rays).filter((type) => type === 'reflect')).toHaveLength(36);
  });
});
