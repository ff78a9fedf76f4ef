import { describe, expect, it } from 'vitest';
import { lengthInside, previewBox, previewPlace, TOP_RIGHT_TOP, type Segment } from '../../../src/ui/lab/preview-place.ts';

// The pixel preview never covers the chosen pixel's rays when it can help it (issue 37):
// at 1366×768 the view is about 786 × 720 px and the preview about 235 × 245.
const view = { width: 786, height: 720 };
const size = { width: 235, height: 245 };
const ray = (x1: number, y1: number, x2: number, y2: number): Segment => ({ from: { x: x1, y: y1 }, to: { x: x2, y: y2 } });

describe('the length of a ray inside a box', () => {
  const box = { left: 10, top: 10, width: 100, height: 50 };
  it('is the part between the sides it crosses', () => {
    expect(lengthInside(ray(0, 20, 200, 20), box)).toBeCloseTo(100);
    expect(lengthInside(ray(0, 5, 120, 65), box)).toBeCloseTo(Math.hypot(100, 50));
    expect(lengthInside(ray(50, 30, 50, 300), box)).toBeCloseTo(30);
  });
  it('is 0 for a ray that passes by or starts beyond it', () => {
    expect(lengthInside(ray(0, 0, 200, 0), box)).toBe(0);
    expect(lengthInside(ray(120, 20, 300, 20), box)).toBe(0);
    expect(lengthInside(ray(20, 70, 20, 70), box)).toBe(0);
  });
});

describe('where the pixel preview goes', () => {
  const home = previewBox('home', view, size);
  const topRight = previewBox('top-right', view, size);
  it('has its home in the lower left and its other place in the upper right, below the buttons', () => {
    expect(home).toEqual({ left: 8, top: 720 - 8 - 245, ...size });
    expect(topRight).toEqual({ left: 786 - 8 - 235, top: TOP_RIGHT_TOP, ...size });
  });
  it('stays home without a chosen pixel, or with rays that run elsewhere', () => {
    expect(previewPlace('home', [], view, size)).toBe('home');
    expect(previewPlace('home', [ray(300, 100, 700, 400)], view, size)).toBe('home');
  });
  it("moves up right when the chosen pixel's rays run under it and not there, and back when they come", () => {
    const underHome = [ray(20, 700, 400, 300), ray(400, 300, 450, 100)];
    expect(previewPlace('home', underHome, view, size)).toBe('top-right');
    // Clear where it is: it stays, even with no pixel's rays under home either.
    expect(previewPlace('top-right', underHome, view, size)).toBe('top-right');
    const underTopRight = [ray(600, 200, 700, 300)];
    expect(previewPlace('top-right', underTopRight, view, size)).toBe('home');
    // Deselected: home again.
    expect(previewPlace('top-right', [], view, size)).toBe('home');
  });
  it('stays where it covers less when rays run under both places', () => {
    const both = [ray(20, 600, 200, 600), ray(600, 300, 650, 300)];
    expect(previewPlace('home', both, view, size)).toBe('top-right');
    expect(previewPlace('top-right', both, view, size)).toBe('top-right');
    const moreUpRight = [ray(20, 600, 60, 600), ray(560, 300, 760, 300)];
    expect(previewPlace('home', moreUpRight, view, size)).toBe('home');
  });
  it('stays home in a small view (a phone, 200 % zoom), whose corners hold the buttons', () => {
    expect(previewPlace('home', [ray(20, 300, 200, 300)], { width: 360, height: 340 }, { width: 200, height: 150 })).toBe('home');
    expect(previewPlace('top-right', [ray(300, 100, 340, 100)], { width: 360, height: 340 }, { width: 200, height: 150 })).toBe('home');
  });
});
