import { describe, expect, it } from 'vitest';
import { DEFAULT_RAY_VIEW, type RayViewOptions } from '../../src/lab-state/lab-state.ts';
import { hexToColor, legendKeys, RAY_COLOR_KEYS, RAY_DASHES, rayPalette, type RayColorKey } from '../../src/view/ray-palette.ts';
import { contributionTone, MIN_ALPHA, MIN_CONTRIBUTION_TONE, NORMAL_LENGTH, type SegmentList, visibleRays } from '../../src/view/ray-visibility.ts';
import type { RayNode } from '../../src/tracer/ray-tree.ts';
import { flattenRays, MISS_LENGTH } from '../../src/view/flat-rays.ts';
import { areaRay, countNodes, ray, screen } from '../support/ray-fixtures.ts';

const options = (changes: Partial<RayViewOptions> = {}): RayViewOptions => ({ ...DEFAULT_RAY_VIEW, ...changes });

/** A primary ray (100 %) that hit, with a light ray (40 %), a shadow ray, a reflection (5 %) with its light ray (2 %), and a missed refraction (1 %). */
function tree(): RayNode {
  return ray('primary', {
    contribution: 1,
    length: 4,
    children: [
      ray('light', { contribution: 0.4, length: 3 }),
      ray('shadow', { contribution: 0, color: [0, 0, 0], length: 1 }),
      ray('reflect', { contribution: 0.05, length: 2, children: [ray('light', { contribution: 0.02, length: 1.5 })] }),
      ray('refract', { contribution: 0.01, hit: false, length: MISS_LENGTH }),
    ],
  });
}

/** The drawn segments as plain objects, for readable assertions. */
function segments(list: SegmentList) {
  return Array.from({ length: list.count }, (_, i) => ({
    type: list.nodes[i].type,
    key: RAY_COLOR_KEYS[list.colorKey[i]],
    contribution: list.nodes[i].contribution,
    length: list.length[i],
    radius: list.radius[i],
    alpha: list.alpha[i],
    start: list.start[i],
    pixel: list.pixel[i],
    color: [...list.color.subarray(i * 3, i * 3 + 3)],
  }));
}

const types = (list: SegmentList) => segments(list).map((s) => s.type);
const twoByTwo = () => screen(2, 2, () => [tree()]);

describe('visibleRays: which rays are drawn', () => {
  it('draws every ray of every pixel with the defaults', () => {
    const rays = twoByTwo();
    const drawn = visibleRays(rays, options(), null);
    expect(drawn.rays.count).toBe(4 * countNodes([tree()]));
    expect(segments(drawn.rays).map((s) => s.pixel)).toEqual([0, 1, 2, 3].flatMap((p) => Array(6).fill(p)));
    expect(drawn.cones.count).toBe(0);
  });

  it('draws nothing when showRays is off, or before anything is traced', () => {
    expect(visibleRays(twoByTwo(), options({ showRays: false }), null).rays.count).toBe(0);
    expect(visibleRays(null, options(), null).rays.count).toBe(0);
  });

  it('draws only the selected pixel, and nothing for a pixel outside the traced screen', () => {
    const rays = screen(3, 2, (x, y) => [ray('primary', { contribution: 1, objectId: `${x},${y}` })]);
    const drawn = visibleRays(rays, options(), [2, 1]);
    expect(drawn.rays.count).toBe(1);
    expect(drawn.rays.nodes[0].objectId).toBe('2,1');
    expect(drawn.rays.pixel[0]).toBe(1 * 3 + 2);
    expect(visibleRays(rays, options(), [3, 0]).rays.count).toBe(0);
    expect(visibleRays(rays, options(), [0, 2]).rays.count).toBe(0);
  });

  it('hides rays that hit nothing when hideNoHit is on', () => {
    const drawn = visibleRays(twoByTwo(), options({ hideNoHit: true }), [0, 0]);
    expect(types(drawn.rays)).toEqual(['primary', 'light', 'shadow', 'reflect', 'light']);
  });

  it('draws missed rays MISS_LENGTH long and red', () => {
    const drawn = visibleRays(
      screen(1, 1, () => [ray('primary', { hit: false, length: 0 })]),
      options(),
      null,
    );
    expect(segments(drawn.rays)[0]).toMatchObject({ length: MISS_LENGTH, key: 'no-hit' });
  });
});

describe('visibleRays: negligible rays', () => {
  it('hides rays below the threshold with their subtrees; a ray exactly at the threshold stays', () => {
    const at = (threshold: number) => types(visibleRays(twoByTwo(), options({ hideNegligible: true, negligibleThreshold: threshold }), [0, 0]).rays);
    expect(at(0)).toEqual(['primary', 'light', 'shadow', 'reflect', 'light', 'refract']);
    expect(at(0.01)).toEqual(['primary', 'light', 'shadow', 'reflect', 'light', 'refract']);
    expect(at(0.0100001)).toEqual(['primary', 'light', 'shadow', 'reflect', 'light']);
    expect(at(0.03)).toEqual(['primary', 'light', 'shadow', 'reflect']);
    // The reflection (5 %) goes, and its light ray (2 %) with it.
    expect(at(0.06)).toEqual(['primary', 'light', 'shadow']);
    expect(at(1)).toEqual(['primary', 'shadow']);
    expect(at(1.0001)).toEqual([]);
  });

  it('hides a subtree with its parent even when a child has a larger share', () => {
    const odd = ray('primary', { contribution: 1, children: [ray('reflect', { contribution: 0.01, children: [ray('light', { contribution: 0.5 })] })] });
    const drawn = visibleRays(
      screen(1, 1, () => [odd]),
      options({ hideNegligible: true, negligibleThreshold: 0.1 }),
      null,
    );
    expect(types(drawn.rays)).toEqual(['primary']);
  });

  it('judges a shadow ray by its parent, since a shadow ray always carries 0 %', () => {
    const hitFrom = (contribution: number) =>
      ray('primary', { contribution: 1, children: [ray('reflect', { contribution, children: [ray('shadow', { contribution: 0 })] })] });
    const hidden = options({ hideNegligible: true, negligibleThreshold: 0.05 });
    expect(
      types(
        visibleRays(
          screen(1, 1, () => [hitFrom(0.2)]),
          hidden,
          null,
        ).rays,
      ),
    ).toEqual(['primary', 'reflect', 'shadow']);
    expect(
      types(
        visibleRays(
          screen(1, 1, () => [hitFrom(0.04)]),
          hidden,
          null,
        ).rays,
      ),
    ).toEqual(['primary']);
  });
});

describe('visibleRays: colour, alpha and radius', () => {
  it('colours rays by type with the VRT palette as display values', () => {
    const drawn = visibleRays(twoByTwo(), options(), [0, 0]);
    const expected: RayColorKey[] = ['primary', 'light', 'shadow', 'reflect', 'light', 'no-hit'];
    const vrt = rayPalette('vrt');
    segments(drawn.rays).forEach((s, i) => {
      expect(s.key).toBe(expected[i]);
      expect(s.color[0]).toBeCloseTo(hexToColor(vrt[expected[i]])[0], 6);
      expect(s.color[1]).toBeCloseTo(hexToColor(vrt[expected[i]])[1], 6);
      expect(s.color[2]).toBeCloseTo(hexToColor(vrt[expected[i]])[2], 6);
    });
    // #70FFFB: 0x70 = 112 → 112 / 255 (no gamma: the lab shows display values).
    expect(segments(drawn.rays)[0].color[0]).toBeCloseTo(112 / 255, 6);
    expect(segments(drawn.rays)[0].color[1]).toBeCloseTo(1, 6);
  });

  it('uses the Okabe–Ito palette when colorBlindPalette is on', () => {
    const drawn = visibleRays(twoByTwo(), options({ colorBlindPalette: true }), [0, 0]);
    const sky = hexToColor('#56B4E9');
    expect(segments(drawn.rays)[0].color).toEqual(sky.map((c) => Math.fround(c)));
    expect(segments(drawn.rays)[5].color).toEqual(hexToColor('#D55E00').map((c) => Math.fround(c)));
  });

  it('the two palettes give eight distinct colours each: six ray kinds, the untested direction and the normal', () => {
    for (const name of ['vrt', 'okabe-ito'] as const) {
      const palette = rayPalette(name);
      expect(new Set(RAY_COLOR_KEYS.map((key) => palette[key])).size).toBe(8);
    }
  });

  it('fades rays toward the fade colour by contribution, a third per decade, never below the faintest tone', () => {
    expect(contributionTone(1)).toBe(1);
    expect(contributionTone(0.1)).toBeCloseTo(2 / 3, 9);
    expect(contributionTone(0.01)).toBeCloseTo(1 / 3, 9);
    expect(contributionTone(0.0001)).toBe(MIN_CONTRIBUTION_TONE);
    expect(contributionTone(0)).toBe(MIN_CONTRIBUTION_TONE);

    const rays = screen(1, 1, () => [ray('primary', { contribution: 1, children: [ray('reflect', { contribution: 0.1 })] })]);
    const dark = segments(visibleRays(rays, options({ contributionColor: true }), null).rays);
    const full = hexToColor(rayPalette('vrt').reflect);
    expect(dark[0].color[1]).toBeCloseTo(1, 6); // the primary ray at 100 % keeps its colour
    dark[1].color.forEach((c, i) => expect(c).toBeCloseTo((full[i] * 2) / 3, 6));

    const white = segments(visibleRays(rays, options({ contributionColor: true }), null, undefined, { fadeTo: [1, 1, 1] }).rays);
    white[1].color.forEach((c, i) => expect(c).toBeCloseTo(1 + ((full[i] - 1) * 2) / 3, 6));
  });

  it('turns transparency into alpha: opaque at 0, almost invisible (MIN_ALPHA) at 1', () => {
    const alpha = (transparency: number) => visibleRays(twoByTwo(), options({ transparency }), [0, 0]).rays.alpha[0];
    expect(alpha(0)).toBe(1);
    expect(alpha(0.5)).toBeCloseTo(1 - 0.5 * (1 - MIN_ALPHA), 6);
    expect(alpha(1)).toBeCloseTo(MIN_ALPHA, 6);
    expect(alpha(3)).toBeCloseTo(MIN_ALPHA, 6);
  });

  it('uses the fixed radius unless the radius is dynamic', () => {
    const radii = segments(visibleRays(twoByTwo(), options({ radius: 0.02 }), [0, 0]).rays).map((s) => s.radius);
    expect(radii.every((r) => Math.abs(r - 0.02) < 1e-9)).toBe(true);
  });

  it('lerps the dynamic radius from min at 0 % to max at 100 %', () => {
    const drawn = segments(visibleRays(twoByTwo(), options({ dynamicRadius: true, minRadius: 0.01, maxRadius: 0.05 }), [0, 0]).rays);
    const expected = [1, 0.4, 1 /* shadow: its parent's 100 % */, 0.05, 0.02, 0.01].map((c) => 0.01 + 0.04 * c);
    drawn.forEach((s, i) => expect(s.radius).toBeCloseTo(expected[i], 6));
  });

  it('allows min > max: small contributions get the big rays', () => {
    const drawn = segments(visibleRays(twoByTwo(), options({ dynamicRadius: true, minRadius: 0.05, maxRadius: 0.01 }), [0, 0]).rays);
    expect(drawn[0].radius).toBeCloseTo(0.01, 6); // 100 %
    expect(drawn[5].radius).toBeCloseTo(0.05 - 0.04 * 0.01, 6); // 1 %
    expect(drawn[5].radius).toBeGreaterThan(drawn[0].radius);
  });
});

describe('visibleRays: area cones', () => {
  it('draws area-light and area-shadow nodes as cones to the light corners, coloured as light and shadow', () => {
    const root = ray('primary', { children: [areaRay('area-light', { contribution: 0.3 }), areaRay('area-shadow', { contribution: 0 })] });
    const drawn = visibleRays(
      screen(1, 1, () => [root]),
      options(),
      null,
    );
    expect(types(drawn.rays)).toEqual(['primary']);
    expect(types(drawn.cones)).toEqual(['area-light', 'area-shadow']);
    expect(segments(drawn.cones).map((s) => s.key)).toEqual(['light', 'shadow']);
    expect([...drawn.cones.corners.subarray(0, 12)]).toEqual([-1, 3, -0.5, 1, 3, -0.5, 1, 3, 0.5, -1, 3, 0.5]);
    expect([...drawn.cones.corners.subarray(12, 24)]).toEqual([-1, 3, -0.5, 1, 3, -0.5, 1, 3, 0.5, -1, 3, 0.5]);
    expect(segments(drawn.cones)[0]).toMatchObject({ length: 3, start: 2 });
  });

  it('applies the same rules to cones (negligible threshold, selected pixel)', () => {
    const root = ray('primary', { children: [areaRay('area-light', { contribution: 0.001 })] });
    const rays = screen(2, 1, () => [root]);
    expect(visibleRays(rays, options(), null).cones.count).toBe(2);
    expect(visibleRays(rays, options(), [1, 0]).cones.count).toBe(1);
    expect(visibleRays(rays, options({ hideNegligible: true, negligibleThreshold: 0.01 }), null).cones.count).toBe(0);
  });
});

describe('visibleRays: animation order', () => {
  it('starts primary rays at 0 and each child when its parent has arrived', () => {
    const drawn = segments(visibleRays(twoByTwo(), options({ animate: true }), [0, 0]).rays);
    expect(drawn.map((s) => s.start)).toEqual([0, 4, 4, 4, 6, 4]);
    expect(visibleRays(twoByTwo(), options(), [0, 0]).travelEnd).toBe(4 + MISS_LENGTH);
  });

  it('pixel by pixel: each pixel starts when the one before has fully grown', () => {
    const rays = screen(3, 1, (x) => [ray('primary', { length: x + 1, children: [ray('light', { length: 1 })] })]);
    const drawn = visibleRays(rays, options({ animate: true, animatePixelByPixel: true }), null);
    // Pixel 0 ends at 1 + 1, pixel 1 (2 + 1 long) at 5, pixel 2 (3 + 1) at 9.
    expect(segments(drawn.rays).map((s) => s.start)).toEqual([0, 1, 2, 4, 5, 8]);
    expect(drawn.travelEnd).toBe(9);
    const together = visibleRays(rays, options({ animate: true }), null);
    expect(segments(together.rays).map((s) => s.start)).toEqual([0, 1, 0, 2, 0, 3]);
  });

  it('reuses its buffers between updates (no growth for the same number of rays)', () => {
    const rays = twoByTwo();
    const first = visibleRays(rays, options(), null);
    const buffer = first.rays.origin;
    const second = visibleRays(rays, options({ transparency: 0.3 }), null, first);
    expect(second).toBe(first);
    expect(second.rays.origin).toBe(buffer);
    expect(second.rays.count).toBe(24);
  });
});

describe('visibleRays: with Shadows off, the direction to a light is drawn as not tested', () => {
  const untested = () =>
    ray('primary', {
      length: 4,
      children: [ray('light', { untested: true, length: 3, contribution: 0.4 }), areaRay('area-light', { untested: true, contribution: 0.3 })],
    });

  it('as its own legend entry, in its own colour and pattern, never as a traced light ray', () => {
    for (const colorBlindPalette of [false, true]) {
      const drawn = visibleRays(
        screen(1, 1, () => [untested()]),
        options({ colorBlindPalette }),
        null,
      );
      const palette = rayPalette(colorBlindPalette ? 'okabe-ito' : 'vrt');
      const [, direction] = segments(drawn.rays);
      expect(direction.key).toBe('untested');
      expect(direction.color).toEqual(hexToColor(palette.untested).map((c) => Math.fround(c)));
      expect(palette.untested).not.toBe(palette.light);
      expect(segments(drawn.cones).map((s) => s.key)).toEqual(['untested']);
    }
    // Sparse dots, unlike every ray's pattern.
    const [dash, gap] = RAY_DASHES.untested;
    expect(gap).toBeGreaterThan(2 * dash);
    const others = RAY_COLOR_KEYS.filter((key) => key !== 'untested').map((key) => RAY_DASHES[key].join('/'));
    expect(others).not.toContain(RAY_DASHES.untested.join('/'));
  });

  it('the legend lists it only while Shadows is off, and always the normal', () => {
    expect(legendKeys(true)).toEqual(['primary', 'light', 'shadow', 'reflect', 'refract', 'no-hit', 'normal']);
    expect(legendKeys(false)).toEqual([...RAY_COLOR_KEYS]);
    expect(legendKeys(false)).toContain('untested');
  });
});

describe('visibleRays: the surface normal at the selected pixel’s hits', () => {
  /** A primary ray down onto the floor (normal +y) and a reflection that hits a wall (normal −x), with a shadow ray. */
  const withNormals = () =>
    ray('primary', {
      origin: [0, 5, 0],
      direction: [0, -1, 0],
      length: 4,
      normal: [0, 1, 0],
      contribution: 0.001,
      children: [
        ray('shadow', { origin: [0, 1, 0], direction: [1, 0, 0], length: 1, contribution: 0, color: [0, 0, 0] }),
        ray('reflect', { origin: [0, 1, 0], direction: [1, 0, 0], length: 2, normal: [-1, 0, 0], contribution: 0.0005 }),
        ray('refract', { origin: [0, 1, 0], direction: [0, -1, 0], hit: false, length: MISS_LENGTH, contribution: 0.0001 }),
      ],
    });

  it('draws a short arrow from each hit along its normal, right after its ray, growing once the ray has arrived', () => {
    const drawn = visibleRays(
      screen(2, 1, () => [withNormals()]),
      options({ contributionColor: true, colorByTime: true }),
      [1, 0],
    );
    const list = drawn.rays;
    expect(segments(list).map((s) => s.key)).toEqual(['primary', 'normal', 'shadow', 'reflect', 'normal', 'no-hit']);
    const at = (i: number) => ({ origin: [...list.origin.subarray(i * 3, i * 3 + 3)], direction: [...list.direction.subarray(i * 3, i * 3 + 3)] });
    expect(at(1)).toEqual({ origin: [0, 1, 0], direction: [0, 1, 0] });
    expect(at(4)).toEqual({ origin: [2, 1, 0], direction: [-1, 0, 0] });
    const normal = segments(list)[4];
    expect(normal).toMatchObject({ length: Math.fround(NORMAL_LENGTH), start: 6, pixel: 1, radius: segments(list)[3].radius });
    expect(list.nodes[4]).toBe(list.nodes[3]);
    // Not a ray: its colour is the palette's, not faded by a tiny contribution.
    expect(normal.color).toEqual(hexToColor(rayPalette('vrt').normal).map((c) => Math.fround(c)));
    expect(drawn.travelEnd).toBe(4 + MISS_LENGTH);
  });

  it('only for one pixel: a whole screen has none; a hidden ray hides its normal', () => {
    const rays = screen(2, 1, () => [withNormals()]);
    expect(segments(visibleRays(rays, options(), null).rays).map((s) => s.key)).not.toContain('normal');
    const hidden = visibleRays(rays, options({ hideNegligible: true, negligibleThreshold: 0.0008 }), [0, 0]);
    expect(segments(hidden.rays).map((s) => s.key)).toEqual(['primary', 'normal', 'shadow']);
  });
});

describe('flattenRays', () => {
  it('flattens each traced screen once, depth first, with each subtree as one index range', () => {
    const rays = twoByTwo();
    const flat = flattenRays(rays);
    expect(flattenRays(rays)).toBe(flat);
    expect(flattenRays(twoByTwo())).not.toBe(flat);
    expect(flat.count).toBe(24);
    expect([...flat.pixelStart]).toEqual([0, 6, 12, 18, 24]);
    expect(flat.nodes.slice(0, 6).map((node) => node.type)).toEqual(['primary', 'light', 'shadow', 'reflect', 'light', 'refract']);
    expect([...flat.subtreeEnd.subarray(0, 6)]).toEqual([6, 2, 3, 5, 5, 6]);
  });
});
