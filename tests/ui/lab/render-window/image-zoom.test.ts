import { describe, expect, it } from 'vitest';
import {
  canvasSizeFor,
  canvasView,
  enlargesFit,
  fitLayout,
  SIDE_BY_SIDE_GAP,
  zoomInStep,
  zoomOutStep,
} from '../../../../src/ui/lab/render-window/image-zoom.ts';

const image = { width: 512, height: 384 };

describe('fitLayout', () => {
  it('fits one image by its tighter side', () => {
    expect(fitLayout({ width: 1024, height: 384 }, image, 'traced')).toEqual({ scale: 1, direction: 'row' });
    expect(fitLayout({ width: 256, height: 768 }, image, 'slider').scale).toBe(0.5);
  });

  it('enlarges a small image to fill the frame', () => {
    expect(fitLayout({ width: 640, height: 480 }, { width: 32, height: 24 }, 'traced').scale).toBe(20);
  });

  it('puts two images in a row in a wide frame and in a column in a tall one', () => {
    const wide = fitLayout({ width: 1024 + SIDE_BY_SIDE_GAP, height: 400 }, image, 'side-by-side');
    expect(wide).toEqual({ scale: 1, direction: 'row' });
    const tall = fitLayout({ width: 512, height: 768 + SIDE_BY_SIDE_GAP }, image, 'side-by-side');
    expect(tall).toEqual({ scale: 1, direction: 'column' });
  });
});

describe('zoom steps', () => {
  it('steps from a fitted scale to the next whole step', () => {
    expect(zoomInStep(0.73)).toBe(1);
    expect(zoomOutStep(0.73)).toBe(0.5);
  });

  it('steps past a scale that is already a step', () => {
    expect(zoomInStep(1)).toBe(2);
    expect(zoomOutStep(2)).toBe(1);
  });

  it('offers 200 % only where it shows the image larger than Fit', () => {
    const small = fitLayout({ width: 640, height: 480 }, { width: 32, height: 24 }, 'traced').scale;
    expect(enlargesFit(2, small)).toBe(false);
    expect(enlargesFit(2, fitLayout({ width: 736, height: 460 }, { width: 320, height: 240 }, 'traced').scale)).toBe(true);
    expect(enlargesFit(2, 2)).toBe(false);
  });

  it('stops at the ends', () => {
    expect(zoomInStep(32)).toBeNull();
    expect(zoomOutStep(1 / 8)).toBeNull();
  });
});

describe('the canvas an image is shown in', () => {
  it('has one pixel per device pixel of its box on screen', () => {
    expect(canvasSizeFor({ width: 4096, height: 4096 }, { width: 600, height: 600 }, 1)).toEqual({ width: 600, height: 600 });
    expect(canvasSizeFor({ width: 4096, height: 3072 }, { width: 601, height: 450 }, 1.25)).toEqual({ width: 751, height: 563 });
  });

  it('never has more pixels than the image, zoomed in or on a dense screen', () => {
    expect(canvasSizeFor(image, { width: 1024, height: 768 }, 1)).toEqual(image);
    expect(canvasSizeFor(image, { width: 400, height: 300 }, 2)).toEqual(image);
  });

  it('keeps at least one pixel a side', () => {
    expect(canvasSizeFor(image, { width: 0, height: 0 }, 1)).toEqual({ width: 1, height: 1 });
  });
});

describe('what the traced canvas shows', () => {
  it('is all of an image shown whole', () => {
    expect(canvasView({ width: 4096, height: 4096 }, { width: 600, height: 600 }, { x: 0, y: 0, width: 600, height: 600 }, 1)).toEqual({
      full: { width: 600, height: 600 },
      window: { x: 0, y: 0, width: 600, height: 600 },
    });
  });

  it('is the part on screen of an image zoomed in, in whole image pixels at most one per device pixel', () => {
    // 4096² at 200 %: a box of 8192 CSS pixels, of which 736 × 460 from (1000.5, 2000) are on screen.
    const view = canvasView({ width: 4096, height: 4096 }, { width: 8192, height: 8192 }, { x: 1000.5, y: 2000, width: 736, height: 460 }, 1);
    expect(view).toEqual({ full: { width: 4096, height: 4096 }, window: { x: 500, y: 1000, width: 369, height: 230 } });
  });

  it('covers the visible part with whole canvas pixels on a dense screen', () => {
    // 100 % on a 1.5× screen: a canvas pixel per image pixel (not more), the box's visible 301 CSS pixels are 301 image pixels.
    const view = canvasView({ width: 2048, height: 1536 }, { width: 2048, height: 1536 }, { x: 100.2, y: 0, width: 301, height: 200 }, 1.5);
    expect(view.window).toEqual({ x: 100, y: 0, width: 302, height: 200 });
  });

  it('keeps at least one pixel inside the image', () => {
    const view = canvasView(image, { width: 512, height: 384 }, { x: 512, y: 384, width: 0, height: 0 }, 1);
    expect(view.window).toEqual({ x: 511, y: 383, width: 1, height: 1 });
  });
});
