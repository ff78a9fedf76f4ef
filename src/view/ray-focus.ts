/**
 * The ray debugger's view of the rays (ray-debugger spec §2): one pixel's trees, only the
 * rays cast so far, all dimmed but one, which is highlighted (drawn thicker and opaque) and,
 * when it was just cast, grows from its origin to its hit. Pure, like ray-visibility.ts:
 * the pool copies the result into its one instanced mesh.
 */
import type { RayViewOptions } from '../lab-state/lab-state.ts';
import type { ScreenRays } from '../render/screen-rays.ts';
import type { PixelTrace, RayNode } from '../tracer/ray-tree.ts';
import { RAY_COLOR_KEY_INDEX } from './ray-palette.ts';
import type { SamplingLobe } from './sampling-lobe.ts';
import { DrawnRays, type RayStyle, type SegmentList, visibleRays } from './ray-visibility.ts';

const NORMAL_KEY = RAY_COLOR_KEY_INDEX.normal;

/** What the debugger asks the pool to draw. */
export interface RayFocus {
  /** The pixel's trace (with or without terms: the rays are the same). */
  trace: PixelTrace;
  /** The rays drawn: those cast so far. */
  shown: ReadonlySet<RayNode>;
  /** The one ray drawn highlighted, or null (all dimmed). */
  highlighted: RayNode | null;
  /** Whether the highlighted ray grows from its origin (it was just cast). */
  grow: boolean;
  /** Rays drawn at full opacity though not highlighted (a path's rays among the pixel's other paths). */
  bright?: ReadonlySet<RayNode>;
  /** Width by each ray's contribution, whatever the ray panel says (a path's throughput). */
  widthByContribution?: boolean;
  /** A pixel's sample paths: bounces solid, light-sampling rays dashed (path-dashes.ts). */
  paths?: boolean;
  /**
   * Every ray keeps its place in the ray panel's animation (it grows after its parent) instead
   * of being there at once: the paths drawn with the debugger closed (path-focus.ts allPathsFocus).
   */
  animated?: boolean;
  /** The sampling distribution drawn at a path's vertex (sampling-lobe.ts), or none. */
  lobe?: SamplingLobe | null;
  /**
   * A click on one of the drawn rays, `at` metres from its origin: returns true when it chose
   * something (the path debugger jumps to the clicked vertex) and the click selects nothing else.
   */
  chooseRay?: (node: RayNode, at: number) => boolean;
}

/** Opacity of the rays that are not highlighted: still there to follow, clearly in the background. */
export const DIMMED_ALPHA = 0.22;

/** The highlighted ray is this many times thicker than the ray panel's radius. */
export const HIGHLIGHT_RADIUS_SCALE = 2.5;

/** A start so far back that the segment has fully grown at any travel ≥ 0. */
const GROWN_LONG_AGO = -1e9;

/** One pixel's trace as a 1×1 screen (cached: the flattened rays are cached per screen object). */
const screens = new WeakMap<PixelTrace, ScreenRays>();
export function screenOf(trace: PixelTrace): ScreenRays {
  let screen = screens.get(trace);
  if (!screen) {
    screen = { columns: 1, rows: 1, traces: [trace] };
    screens.set(trace, screen);
  }
  return screen;
}

/**
 * The segments for `focus`: the panel's colours and radius, every filter off (the debugger
 * shows every ray it steps through), then only the shown rays kept, dimmed but the highlighted.
 * `travelEnd` is where the highlighted ray (and the normal at its hit) has grown when it grows,
 * else 0 (nothing to animate).
 */
export function focusedRays(focus: RayFocus, options: RayViewOptions, into = new DrawnRays(), style?: RayStyle): DrawnRays {
  const all: RayViewOptions = {
    ...options,
    showRays: true,
    hideNoHit: false,
    hideNegligible: false,
    transparency: 0,
    animatePixelByPixel: false,
    ...(focus.widthByContribution ? { dynamicRadius: true } : {}),
  };
  // Every glossy ray as itself: the debugger steps through (and highlights) each one. The
  // pixel as the chosen one of its 1 × 1 screen, so its hits show their normals.
  visibleRays(screenOf(focus.trace), all, [0, 0], into, style, false);
  let travelEnd = 0;
  for (const list of [into.rays, into.cones]) {
    let kept = 0;
    for (let i = 0; i < list.count; i++) {
      const node = list.nodes[i];
      if (!focus.shown.has(node)) continue;
      moveSegment(list, i, kept);
      // A normal comes and goes with its ray, and grows from its hit once the ray has arrived.
      const normal = list.colorKey[kept] === NORMAL_KEY;
      const highlighted = node === focus.highlighted;
      const grows = highlighted && focus.grow;
      list.alpha[kept] = highlighted || focus.bright?.has(node) ? 1 : DIMMED_ALPHA;
      if (highlighted && !normal) list.radius[kept] *= HIGHLIGHT_RADIUS_SCALE;
      if (!focus.animated) list.start[kept] = grows ? (normal ? node.length : 0) : GROWN_LONG_AGO;
      if (grows || focus.animated) travelEnd = Math.max(travelEnd, list.start[kept] + list.length[kept]);
      kept++;
    }
    list.count = kept;
    list.nodes.length = kept;
  }
  into.travelEnd = travelEnd;
  return into;
}

/** Copies segment `from` over segment `to` (to ≤ from), every array. */
function moveSegment(list: SegmentList, from: number, to: number): void {
  if (from === to) return;
  list.nodes[to] = list.nodes[from];
  list.origin.copyWithin(to * 3, from * 3, from * 3 + 3);
  list.direction.copyWithin(to * 3, from * 3, from * 3 + 3);
  list.color.copyWithin(to * 3, from * 3, from * 3 + 3);
  list.length[to] = list.length[from];
  list.radius[to] = list.radius[from];
  list.alpha[to] = list.alpha[from];
  list.start[to] = list.start[from];
  list.colorKey[to] = list.colorKey[from];
  list.pixel[to] = list.pixel[from];
  if (list.withCorners) list.corners.copyWithin(to * 12, from * 12, from * 12 + 12);
}
