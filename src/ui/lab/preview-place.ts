import type { ReactiveController, ReactiveControllerHost } from 'lit';
import type { LabView } from '../../view/lab-view.ts';

/**
 * Where the pixel preview sits over the 3D view (issue 37: it must never cover the rays a
 * task names). Its home is the view's lower left corner, and the view frames what a task
 * shows into the part above it (view-cover.ts). A pixel the learner picks that the view did
 * not frame, or an orbit, can still run the chosen pixel's rays under it: then, once the view
 * has stopped moving, the preview moves to the upper right corner (below the view's buttons)
 * if fewer of those rays run there, and back home when they run there again or no pixel is
 * chosen. A small view (a phone, 200 % zoom) keeps it home: its corners hold the view's
 * buttons and legend.
 */
export type PreviewPlace = 'home' | 'top-right';

type Point = { x: number; y: number };
export type Segment = { from: Point; to: Point };
/** CSS px, from the canvas's top-left corner. */
export interface Box {
  left: number;
  top: number;
  width: number;
  height: number;
}

/** The gap between the preview and the view's edge (--rt-space). */
export const PREVIEW_MARGIN = 8;
/**
 * The upper right place's top: below the view's top buttons and the "Debug a pixel" button
 * (lab-layout.css.ts places `rt-screen-preview[data-place='top-right']` there too).
 */
export const TOP_RIGHT_TOP = 148;
/** Below this view height the preview stays home (lab-compact.css.ts's small view). */
const SMALL_VIEW_HEIGHT = 480;
/** Ray length (px) a place may cover and still count as clear: an end of a ray grazing its corner. */
const CLEAR_PX = 8;

/** The preview's box at `place` in a view of `view` size, the preview being `size` large. */
export function previewBox(place: PreviewPlace, view: { width: number; height: number }, size: { width: number; height: number }): Box {
  return place === 'home'
    ? { left: PREVIEW_MARGIN, top: view.height - PREVIEW_MARGIN - size.height, ...size }
    : { left: view.width - PREVIEW_MARGIN - size.width, top: TOP_RIGHT_TOP, ...size };
}

/** How long a stretch of `segment` lies inside `box` (px): the segment clipped to the box (Liang–Barsky). */
export function lengthInside(segment: Segment, box: Box): number {
  const dx = segment.to.x - segment.from.x;
  const dy = segment.to.y - segment.from.y;
  let enter = 0;
  let leave = 1;
  // Each side of the box as p·t ≤ q: the segment's parameter t is inside for all four.
  const sides: [number, number][] = [
    [-dx, segment.from.x - box.left],
    [dx, box.left + box.width - segment.from.x],
    [-dy, segment.from.y - box.top],
    [dy, box.top + box.height - segment.from.y],
  ];
  for (const [p, q] of sides) {
    if (p === 0) {
      if (q < 0) return 0;
      continue;
    }
    const t = q / p;
    if (p < 0) enter = Math.max(enter, t);
    else leave = Math.min(leave, t);
  }
  return leave > enter ? (leave - enter) * Math.hypot(dx, dy) : 0;
}

const coveredLength = (segments: Segment[], box: Box) => segments.reduce((sum, segment) => sum + lengthInside(segment, box), 0);

/**
 * Where the preview goes: home, unless the chosen pixel's rays (`segments`, none without a
 * chosen pixel) run under it there and fewer of them under the upper right place; staying
 * where it is while it covers none of them, so it does not jump about as the rays change.
 */
export function previewPlace(
  now: PreviewPlace,
  segments: Segment[],
  view: { width: number; height: number },
  size: { width: number; height: number },
): PreviewPlace {
  if (segments.length === 0 || view.height < SMALL_VIEW_HEIGHT || size.width === 0) return 'home';
  const covered = (place: PreviewPlace) => coveredLength(segments, previewBox(place, view, size));
  if (covered(now) <= CLEAR_PX) return now;
  const other: PreviewPlace = now === 'home' ? 'top-right' : 'home';
  return covered(other) < covered(now) ? other : now;
}

/**
 * Keeps the preview in its place (`data-place` on the element, styled by lab-layout.css.ts):
 * checked on every frame the 3D view draws while it is not moving (an idle view draws none).
 */
export class PreviewPlaceController implements ReactiveController {
  private view: LabView | null = null;
  private stop: (() => void) | null = null;

  constructor(
    host: ReactiveControllerHost,
    private readonly parts: () => { view: LabView | null; preview: HTMLElement | null },
  ) {
    host.addController(this);
  }

  hostUpdated(): void {
    const { view } = this.parts();
    if (view === this.view) return;
    this.stop?.();
    this.view = view;
    this.stop = view ? view.addAnimator(() => this.place()) : null;
  }

  hostDisconnected(): void {
    this.stop?.();
    this.stop = null;
    this.view = null;
  }

  /** An animator that never asks for frames of its own: it looks at the ones drawn anyway. */
  private place(): boolean {
    const { view, preview } = this.parts();
    if (!view || !preview || view.moving) return false;
    const now: PreviewPlace = preview.dataset.place === 'top-right' ? 'top-right' : 'home';
    const canvas = view.canvas.getBoundingClientRect();
    const next = previewPlace(now, view.pixelRaySegments(), canvas, { width: preview.offsetWidth, height: preview.offsetHeight });
    if (next !== now) preview.dataset.place = next;
    return false;
  }
}
