import { describe, expect, it } from 'vitest';
import { DEFAULT_RAY_VIEW } from '../../src/lab-state/lab-state.ts';
import { paletteNameFor, rayColor } from '../../src/view/ray-palette.ts';
import { visibleRays } from '../../src/view/ray-visibility.ts';
import { timeColor, timeGradient } from '../../src/view/time-colors.ts';
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
    const stops = [...timeGradient().matchAll(/rgb\((\d+) (\d+) (\d+)\) ([\d.]+)%/g)].map((m) => ({ rgb: [Number(m[1]), Number(m[2]), Number(m[3])], at: Number(m[4]) }));
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
