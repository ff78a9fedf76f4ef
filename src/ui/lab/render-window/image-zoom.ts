/**
 * Zoom and layout of the render window's image(s): the scale that fits them in their frame,
 * the fixed zoom steps, which way two images sit side by side, and which canvas pixels show
 * the ray traced one.
 */

export type CompareMode = 'traced' | 'side-by-side' | 'slider';

export interface Size {
  width: number;
  height: number;
}

/** Screen pixels per image pixel: the zoom buttons step through these (× 2 each). */
export const ZOOM_STEPS: readonly number[] = [1 / 8, 1 / 4, 1 / 2, 1, 2, 4, 8, 16, 32];

/** CSS pixels between the two images of the side-by-side comparison. */
export const SIDE_BY_SIDE_GAP = 8;

export interface ImageLayout {
  /** Screen pixels per image pixel. */
  scale: number;
  /** Side by side: next to each other ('row') or one above the other ('column'). */
  direction: 'row' | 'column';
}

/**
 * The largest scale at which the image (two of them side by side) fits in `frame`. Side by
 * side, the images go next to each other or one above the other, whichever shows them bigger:
 * a wide window puts them in a row, a tall one in a column.
 */
export function fitLayout(frame: Size, image: Size, mode: CompareMode): ImageLayout {
  const single = Math.min(frame.width / image.width, frame.height / image.height);
  if (mode !== 'side-by-side') return { scale: single, direction: 'row' };
  const row = Math.min((frame.width - SIDE_BY_SIDE_GAP) / (2 * image.width), frame.height / image.height);
  const column = Math.min(frame.width / image.width, (frame.height - SIDE_BY_SIDE_GAP) / (2 * image.height));
  return row >= column ? { scale: row, direction: 'row' } : { scale: column, direction: 'column' };
}

/**
 * The next zoom step above `scale`, or null at the largest. A scale that is already (almost)
 * a step goes to the one after it; from "fit" at 73 % it goes to 100 %.
 */
export function zoomInStep(scale: number): number | null {
  return ZOOM_STEPS.find((step) => step > scale * 1.001) ?? null;
}

/**
 * Whether the fixed zoom `scale` (200 %) shows the image larger than Fit does: for a small
 * image Fit is already larger (a 32 × 24 image fits a 640 × 480 frame at 2000 %), and a
 * button labelled 200 % that shrinks the image would contradict its label.
 */
export function enlargesFit(scale: number, fitScale: number): boolean {
  return scale > fitScale * 1.001;
}

/** The next zoom step below `scale`, or null at the smallest. */
export function zoomOutStep(scale: number): number | null {
  return [...ZOOM_STEPS].reverse().find((step) => step < scale / 1.001) ?? null;
}

export interface Rect extends Size {
  x: number;
  y: number;
}

/**
 * What a canvas shows of an image: the whole image at the canvas's scale would be `full`
 * canvas pixels; the canvas is its `window` part (in those pixels), the part on screen.
 */
export interface CanvasView {
  full: Size;
  window: Rect;
}

/**
 * The whole pixels [first, end) of a grid `scale` times as fine (0..length) that the span
 * [start, end) overlaps; an edge a rounding error past a pixel's edge does not count.
 */
export function pixelsCovering(start: number, end: number, scale: number, length: number): [number, number] {
  return [Math.max(0, Math.floor(start * scale + 1e-9)), Math.min(length, Math.ceil(end * scale - 1e-9))];
}

export function sameRect(a: Rect, b: Rect): boolean {
  return a.x === b.x && a.y === b.y && a.width === b.width && a.height === b.height;
}

export function sameView(a: CanvasView, b: CanvasView | null): boolean {
  return b !== null && a.full.width === b.full.width && a.full.height === b.full.height && sameRect(a.window, b.window);
}

/**
 * The canvas size that shows an `image` in a box of `shown` CSS pixels: one canvas pixel per
 * device pixel of the box, never more than the image's own pixels. A canvas as large as a
 * 4096² image cost the page 40 ms to size and 56–260 ms per changed frame for a compositor
 * on the CPU to copy (docs/benchmark-log.md, eighteenth round).
 */
export function canvasSizeFor(image: Size, shown: Size, devicePixelRatio: number): Size {
  const side = (own: number, onScreen: number) => Math.min(own, Math.max(1, Math.round(onScreen * devicePixelRatio)));
  return { width: side(image.width, shown.width), height: side(image.height, shown.height) };
}

/**
 * The canvas for an image shown in a box of `shown` CSS pixels of which the part `visible`
 * (CSS pixels from the box's top left) is on screen: its scale as canvasSizeFor's, its
 * window the whole canvas pixels that cover the visible part (at least one).
 */
export function canvasView(image: Size, shown: Size, visible: Rect, devicePixelRatio: number): CanvasView {
  const full = canvasSizeFor(image, shown, devicePixelRatio);
  const span = (from: number, length: number, shownLength: number, fullLength: number): [number, number] => {
    const [first, end] = pixelsCovering(from, from + length, fullLength / Math.max(1, shownLength), fullLength);
    const start = Math.min(fullLength - 1, first);
    return [start, Math.max(start + 1, end)];
  };
  const [left, right] = span(visible.x, visible.width, shown.width, full.width);
  const [top, bottom] = span(visible.y, visible.height, shown.height, full.height);
  return { full, window: { x: left, y: top, width: right - left, height: bottom - top } };
}
