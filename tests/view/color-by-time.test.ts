import { describe, expect, it } from 'vitest';
import type { InstancedMesh } from 'three';
import { DEFAULT_RAY_VIEW } from '../../src/lab-state/lab-state.ts';
import { RAY_CYLINDERS_NAME, RayPool } from '../../src/view/ray-pool.ts';
import { DASH_ATTRIBUTE } from '../../src/view/ray-shader.ts';
import { paletteNameFor, RAY_DASHES, rayColor } from '../../src/view/ray-palette.ts';
import { visibleRays } from '../../src/view/ray-visibility.ts';
import { TIME_STRIPE_PERIOD, TIME_STRIPE_SHARE, timeColor, timeGradient, timeStripe } from '../../src/view/time-colors.ts';
import { ray, screen } from '../support/ray-fixtures.ts';

/** Colour by time (distribution-effects §4): the rays of a time sample take that time's colour. */

const tree = () => [
  ray('primary', {
    children: [
      ray('primary', { time: 0.1, children: [ray('reflect', { children: [ray('light')] })] }),
      ray('primary', { time: 0.8, children: [ray('shadow', { color: [0, 0, 0] })] }),
    ],
  }),
];

function colors(colorByTime: boolean): number[][] {
  const drawn = visibleRays(screen(1, 1, tree), { ...DEFAULT_RAY_VIEW, colorByTime }, null);
  return Array.from({ length: drawn.rays.count }, (_, i) => Array.from(drawn.rays.color.subarray(i * 3, i * 3 + 3)));
}

const rgb = (values: ArrayLike<number>) => Array.from(Float32Array.from(values));

describe('colour by time', () => {
  it('gives a time ray and its whole subtree the colour of its time; the pinhole root keeps its type', () => {
    const early = new Float32Array(3);
    const late = new Float32Array(3);
    timeColor(Math.fround(0.1), early);
    timeColor(Math.fround(0.8), late); // times are kept as 32-bit floats
    const primary = rgb(rayColor(paletteNameFor(false), 'primary'));
    expect(colors(true)).toEqual([primary, rgb(early), rgb(early), rgb(early), rgb(late), rgb(late)]);
  });

  it('off, every ray has its type colour', () => {
    const palette = paletteNameFor(false);
    expect(colors(false)).toEqual(['primary', 'primary', 'reflect', 'light', 'primary', 'shadow'].map((key) => rgb(rayColor(palette, key as 'primary'))));
  });

  it('runs from dark to bright: brightness alone orders the times', () => {
    const luminance = (t: number) => {
      const c = [0, 0, 0];
      timeColor(t, c);
      return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
    };
    for (let t = 0; t < 1; t += 0.1) expect(luminance(t + 0.1)).toBeGreaterThan(luminance(t));
  });
});

describe('the time ramp as a CSS gradient (the legend’s key)', () => {
  it('has the colours rays are drawn in at τ = 0, ¼, ½, ¾ and 1, from left to right', () => {
    const stops = [...timeGradient().matchAll(/rgb\((\d+) (\d+) (\d+)\) ([\d.]+)%/g)].map((m) => ({
      rgb: [Number(m[1]), Number(m[2]), Number(m[3])],
      at: Number(m[4]),
    }));
    expect(timeGradient().startsWith('linear-gradient(90deg, ')).toBe(true);
    expect(stops.map((stop) => stop.at)).toEqual([0, 25, 50, 75, 100]);
    for (const stop of stops) {
      const drawn = [0, 0, 0];
      timeColor(stop.at / 100, drawn);
      expect(stop.rgb).toEqual(drawn.map((value) => Math.round(value * 255)));
    }
    // Dark at the opening, bright at the closing: brightness alone orders the times.
    expect(stops[0].rgb.reduce((a, b) => a + b)).toBeLessThan(stops[4].rgb.reduce((a, b) => a + b));
  });
});

describe('rays of several moments along one line', () => {
  /** Where along a ray (as a share of the period) a moment's stripe is drawn, as the shader keeps it: fract(along / period − τ) ≤ share. */
  const drawnAt = (dash: ArrayLike<number>, share: number) => (along: number) => {
    const x = (along / dash[1]! + dash[0]! + 1) % 1;
    return (x + 1) % 1 <= share;
  };

  it('stripes each time ray at its moment, and leaves the others to their type’s dashes', () => {
    const drawn = visibleRays(screen(1, 1, tree), { ...DEFAULT_RAY_VIEW, colorByTime: true }, null);
    expect(Array.from(drawn.rays.moment.subarray(0, drawn.rays.count))).toEqual([
      -1,
      Math.fround(0.1),
      Math.fround(0.1),
      Math.fround(0.1),
      Math.fround(0.8),
      Math.fround(0.8),
    ]);
    const off = visibleRays(screen(1, 1, tree), { ...DEFAULT_RAY_VIEW, colorByTime: false }, null);
    expect(Array.from(off.rays.moment.subarray(0, off.rays.count)).every((moment) => moment === -1)).toBe(true);
  });

  it('hands the stripes to the shader in the rays’ dash attribute', () => {
    const pool = new RayPool();
    pool.update(screen(1, 1, tree), { ...DEFAULT_RAY_VIEW, colorByTime: true }, null);
    const dash = (pool.object.getObjectByName(RAY_CYLINDERS_NAME) as InstancedMesh).geometry.getAttribute(DASH_ATTRIBUTE);
    const late = new Float32Array(2);
    timeStripe(Math.fround(0.8), late, 0);
    expect([dash.getX(0), dash.getY(0)]).toEqual([...RAY_DASHES.primary]); // the pinhole root has no time
    expect([dash.getX(5), dash.getY(5)]).toEqual([...late]);
  });

  it('lets the grid’s four moments take turns along the line, each its own colour, none covering another', () => {
    const moments = [0.125, 0.375, 0.625, 0.875];
    const stripes = moments.map((moment) => {
      const dash = new Float32Array(2);
      timeStripe(moment, dash, 0);
      expect(dash[0]).toBeLessThan(0); // a stripe, not a type's dash
      return drawnAt(dash, TIME_STRIPE_SHARE);
    });
    // Sampled along two periods: every point is drawn by exactly one moment's ray.
    for (let along = 0.001; along < 2 * TIME_STRIPE_PERIOD; along += TIME_STRIPE_PERIOD / 97) {
      expect(stripes.filter((drawnHere) => drawnHere(along)).length, `at ${along.toFixed(3)} m`).toBe(1);
    }
    // And the four colours differ clearly from one another (each channel pair apart by more than 0.1 somewhere).
    const colours = moments.map((moment) => {
      const c = [0, 0, 0];
      timeColor(moment, c);
      return c;
    });
    for (const [i, a] of colours.entries())
      for (const b of colours.slice(i + 1)) expect(Math.max(...a.map((value, axis) => Math.abs(value - b[axis]!)))).toBeGreaterThan(0.2);
  });
});
