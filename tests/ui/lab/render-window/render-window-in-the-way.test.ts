import { describe, expect, it } from 'vitest';
import { boxesOverlap, renderWindowInTheWay } from '../../../../src/ui/lab/render-window/render-window-in-the-way.ts';

const NOTHING = { ring: null, look: null };
const covered = () => true;
const beside = () => false;

describe('renderWindowInTheWay', () => {
  it('leaves the window open when the next task moves nothing (levels 9-11: the render stays on show)', () => {
    expect(renderWindowInTheWay(NOTHING, { ring: null, look: null }, covered)).toBe(false);
  });

  it('closes it for a task view that frames objects in 3D or looks through the camera', () => {
    expect(renderWindowInTheWay(NOTHING, { ring: null, look: { frame: ['ball'] } }, beside)).toBe(true);
    expect(renderWindowInTheWay(NOTHING, { ring: null, look: { throughCamera: true } }, beside)).toBe(true);
  });

  it('does not close it again for the same view, nor for a view that only sets where from', () => {
    const look = { frame: ['ball'] };
    expect(renderWindowInTheWay({ ring: null, look }, { ring: null, look }, covered)).toBe(false);
    expect(renderWindowInTheWay(NOTHING, { ring: null, look: { from: [1, 0, 0] } }, covered)).toBe(false);
  });

  it('closes it for a new hint ring only when the window covers the ringed control', () => {
    expect(renderWindowInTheWay(NOTHING, { ring: 'tracer.supersampling', look: null }, beside)).toBe(false);
    expect(renderWindowInTheWay(NOTHING, { ring: 'object:ball', look: null }, covered)).toBe(true);
    expect(renderWindowInTheWay({ ring: 'object:ball', look: null }, { ring: 'object:ball', look: null }, covered)).toBe(false);
  });

  it('never closes it for a ring on its own controls', () => {
    expect(renderWindowInTheWay(NOTHING, { ring: 'render.save', look: null }, covered)).toBe(false);
  });
});

describe('boxesOverlap', () => {
  const box = (left: number, top: number, width: number, height: number) => ({ left, top, right: left + width, bottom: top + height });
  it('overlaps boxes that share an area, not boxes that only touch or are apart', () => {
    expect(boxesOverlap(box(0, 0, 10, 10), box(5, 5, 10, 10))).toBe(true);
    expect(boxesOverlap(box(0, 0, 10, 10), box(10, 0, 10, 10))).toBe(false);
    expect(boxesOverlap(box(0, 0, 10, 10), box(30, 30, 5, 5))).toBe(false);
    expect(boxesOverlap(box(0, 0, 0, 0), box(8, 8, 100, 100))).toBe(false);
  });
});
