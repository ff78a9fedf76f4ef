import { describe, expect, it } from 'vitest';
import { InstancedMesh, type InstancedBufferAttribute } from 'three';
import { DEFAULT_RAY_VIEW } from '../../src/lab-state/lab-state.ts';
import type { PixelTrace, RayNode } from '../../src/tracer/ray-tree.ts';
import { DIMMED_ALPHA, focusedRays, HIGHLIGHT_RADIUS_SCALE } from '../../src/view/ray-focus.ts';
import { RAY_CONES_NAME, RAY_CYLINDERS_NAME, RayPool } from '../../src/view/ray-pool.ts';
import { ALPHA_ATTRIBUTE, GROWTH_ATTRIBUTE } from '../../src/view/ray-shader.ts';
import { RAY_COLOR_KEYS } from '../../src/view/ray-palette.ts';
import { NORMAL_LENGTH } from '../../src/view/ray-visibility.ts';
import { areaRay, ray } from '../support/ray-fixtures.ts';

/** A primary ray (4 m) with a light ray, an area-light cone and a reflection (2 m) that has its own shadow ray. */
function tree(): { trace: PixelTrace; rays: RayNode[] } {
  const shadow = ray('shadow', { length: 1 });
  const reflect = ray('reflect', { length: 2, children: [shadow] });
  const light = ray('light', { length: 3 });
  const cone = areaRay('area-light');
  const primary = ray('primary', { length: 4, children: [light, cone, reflect] });
  return { trace: { pixel: [0, 0], color: [0.1, 0.2, 0.3], rays: [primary] }, rays: [primary, light, cone, reflect, shadow] };
}

describe('the ray debugger’s focus (ray-focus.ts)', () => {
  it('draws only the rays cast so far, all dimmed but the highlighted one, which is thicker and grows from 0', () => {
    const { trace, rays } = tree();
    const [primary, light, cone, reflect] = rays;
    const drawn = focusedRays({ trace, shown: new Set([primary, light, cone, reflect]), highlighted: reflect, grow: true }, DEFAULT_RAY_VIEW);

    expect(drawn.rays.nodes).toEqual([primary, light, reflect]);
    expect(drawn.cones.nodes).toEqual([cone]);
    expect(Array.from(drawn.rays.alpha.subarray(0, 3))).toEqual([DIMMED_ALPHA, DIMMED_ALPHA, 1].map(Math.fround));
    expect(drawn.cones.alpha[0]).toBe(Math.fround(DIMMED_ALPHA));
    expect(drawn.rays.radius[2]).toBeCloseTo(DEFAULT_RAY_VIEW.radius * HIGHLIGHT_RADIUS_SCALE, 6);
    expect(drawn.rays.radius[0]).toBeCloseTo(DEFAULT_RAY_VIEW.radius, 6);
    // The highlighted ray starts at travel 0 and ends at its length; the others have grown long ago.
    expect(drawn.rays.start[2]).toBe(0);
    expect(drawn.rays.start[0]).toBeLessThan(-1e6);
    expect(drawn.travelEnd).toBe(2);
    // Its own origin and direction, after the dropped rays were squeezed out.
    expect(Array.from(drawn.rays.origin.subarray(6, 9))).toEqual(reflect.origin);
  });

  it('a ray shown again (not just cast) stands fully grown; the panel’s filters do not hide what the debugger steps through', () => {
    const { trace, rays } = tree();
    const options = { ...DEFAULT_RAY_VIEW, showRays: false, hideNegligible: true, negligibleThreshold: 2, transparency: 1 };
    const drawn = focusedRays({ trace, shown: new Set(rays), highlighted: rays[0], grow: false }, options);
    expect(drawn.rays.count + drawn.cones.count).toBe(rays.length);
    expect(drawn.rays.alpha[0]).toBe(1);
    expect(drawn.travelEnd).toBe(0);
  });

  it('draws the normal at each shown hit with its ray, dimmed or lit like it, growing from the hit after the ray', () => {
    const { trace, rays } = tree();
    const [primary, light, , reflect] = rays;
    primary.normal = [0, 0, 1];
    reflect.normal = [0, -1, 0];
    const drawn = focusedRays({ trace, shown: new Set([primary, light, reflect]), highlighted: reflect, grow: true }, DEFAULT_RAY_VIEW);
    expect(drawn.rays.nodes).toEqual([primary, primary, light, reflect, reflect]);
    expect(Array.from(drawn.rays.colorKey.subarray(0, 5)).map((key) => RAY_COLOR_KEYS[key])).toEqual(['primary', 'normal', 'light', 'reflect', 'normal']);
    expect(Array.from(drawn.rays.alpha.subarray(0, 5))).toEqual([DIMMED_ALPHA, DIMMED_ALPHA, DIMMED_ALPHA, 1, 1].map(Math.fround));
    // The highlighted reflection grows over its 2 m, then its normal (not thickened) from its hit.
    expect(drawn.rays.start[4]).toBe(2);
    expect(drawn.rays.radius[4]).toBeCloseTo(DEFAULT_RAY_VIEW.radius, 6);
    expect(drawn.travelEnd).toBeCloseTo(2 + NORMAL_LENGTH, 6);
    // A hit not yet reached shows no normal.
    const early = focusedRays({ trace, shown: new Set([primary]), highlighted: primary, grow: false }, DEFAULT_RAY_VIEW);
    expect(early.rays.nodes).toEqual([primary, primary]);
  });

  it('the pool draws the focus in its one cylinder mesh instead of the screen, and back', () => {
    const { trace, rays } = tree();
    const pool = new RayPool();
    const screen = { columns: 1, rows: 1, traces: [trace] };
    pool.update(screen, DEFAULT_RAY_VIEW, null);
    expect(pool.stats).toMatchObject({ rays: 4, cones: 1 });

    pool.setFocus({ trace, shown: new Set(rays.slice(0, 2)), highlighted: rays[1], grow: true });
    pool.update(screen, DEFAULT_RAY_VIEW, null);
    const cylinders = pool.object.getObjectByName(RAY_CYLINDERS_NAME) as InstancedMesh;
    const alpha = cylinders.geometry.getAttribute(ALPHA_ATTRIBUTE) as InstancedBufferAttribute;
    const growth = cylinders.geometry.getAttribute(GROWTH_ATTRIBUTE) as InstancedBufferAttribute;
    expect(pool.stats).toMatchObject({ rays: 2, cones: 0, arrows: 2, drawCalls: 3 });
    expect([alpha.getX(0), alpha.getX(1)]).toEqual([Math.fround(DIMMED_ALPHA), 1]);
    expect(growth.getX(1)).toBe(0);
    // It grows over its 3 m at 4 m/s, then stops asking for frames.
    expect(pool.tick(1000)).toBe(true);
    expect(pool.tick(1500)).toBe(true);
    expect(pool.tick(2000)).toBe(false);
    expect((pool.object.getObjectByName(RAY_CONES_NAME) as InstancedMesh).visible).toBe(false);

    pool.setFocus(null);
    pool.update(screen, DEFAULT_RAY_VIEW, null);
    expect(pool.stats).toMatchObject({ rays: 4, cones: 1 });
    expect(pool.tick(3000)).toBe(false);
  });
});
