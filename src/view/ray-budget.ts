/**
 * A budget for the rays the lab's 3D view draws while the learner edits. On a CPU rasterizer
 * (SwiftShader, llvmpipe) every drawn ray costs fill time, and the free lab's largest
 * settings draw tens of thousands of rays, seconds a frame there (docs/benchmark-log.md), so
 * the view froze while a slider moved. While the learner edits, a screen of more than
 * EDIT_RAY_BUDGET rays is drawn with about HEAVY_EDIT_RAYS of them, chosen by the rule of
 * tracer/tree-budget.ts (whole trees, spread over the screen, the chosen pixel's and every
 * kind kept); once the edits stop, all of them (RayBudgetWhileEditing).
 */
import type { ScreenRays } from '../render/screen-rays.ts';
import { type BudgetTrees, countsEveryRay, keptTrees, tracedRays } from '../tracer/tree-budget.ts';
import type { FlatRays } from './flat-rays.ts';
import { RAY_COLOR_KEYS } from './ray-palette.ts';
import type { DrawnRays } from './ray-visibility.ts';

/**
 * The most rays (and cones) a screen may have to be drawn whole while the learner edits, on
 * a CPU rasterizer. On SwiftShader a frame of the lab's view at the coarse resolution of an
 * edit (BurstResolution) cost about 20 ms plus 0.035 ms per drawn ray, the see-through
 * ribbons' fill (docs/benchmark-log.md): 1,200 rays keep it near 60 ms. Every level's own
 * screens draw fewer (at most 957, level 18's; tests/view/ray-budget.test.ts), so a teaching
 * view is never thinned.
 */
export const EDIT_RAY_BUDGET = 1200;

/**
 * The rays (and cones) drawn per frame while the learner edits a screen that has more than
 * EDIT_RAY_BUDGET: one that must be thinned anyway is thinned to this. A dragged slider asks
 * for a frame every frame, and SwiftShader draws each instance of an instanced draw as a draw
 * of its own, about 33 µs a ray whatever the resolution: 400 rays added 8 ms to a 19 ms frame
 * of the lab's view, 150 rays 3 ms (docs/benchmark-log.md, issue 38). A few whole trees
 * still show every kind and spread over the screen (tracer/tree-budget.ts).
 */
export const HEAVY_EDIT_RAYS = 150;

/**
 * How many rays `screen` is drawn with while the learner edits: all of a screen within
 * EDIT_RAY_BUDGET, else HEAVY_EDIT_RAYS. A screen traced from one sample per pixel was
 * traced so because it was heavy (tracesOneSample).
 */
export function editBudgetFor(screen: ScreenRays | null): number {
  return screen !== null && (!countsEveryRay(screen.traces) || tracedRaysOf(screen) > EDIT_RAY_BUDGET) ? HEAVY_EDIT_RAYS : EDIT_RAY_BUDGET;
}

/**
 * Whether the worker traces each pixel from one of its samples, uncounted, under `budget`
 * (workers/protocol.ts, RayBudget): for a heavy screen, where counting every ray only to
 * draw HEAVY_EDIT_RAYS of them kept a core busy for the whole of a drag (docs/benchmark-log.md,
 * issue 38). A lighter screen is traced whole and counted, as the levels' are.
 */
export function tracesOneSample(budget: number): boolean {
  return budget === HEAVY_EDIT_RAYS;
}

/**
 * How many rays are drawn (`shown`) of how many were traced (`of`) while a budget leaves some
 * out; when the screen was traced from one sample per pixel (`oneSample`), nothing counted
 * its rays, and `of` is the count of the last screen traced whole, before the edit (or null).
 */
export interface Thinning {
  shown: number;
  of: number | null;
  oneSample: boolean;
}

/**
 * Which rays of the flattened screen `budget` keeps (ray-visibility.ts's `kept`: 1 for a
 * drawn ray), by the rule of tracer/tree-budget.ts, every ray of pixel `keepPixel` (y ·
 * columns + x, or null) among them; null when the screen has no more rays than that.
 */
export function keptRays(flat: FlatRays, budget: number, keepPixel: number | null): Uint8Array | null {
  if (flat.count <= budget) return null;
  const known = keptByScreen.get(flat);
  if (known && known.budget === budget && known.keepPixel === keepPixel) return known.kept;
  const trees = flatTrees(flat);
  const keep = keptTrees(trees, budget, keepPixel);
  const kept = new Uint8Array(flat.count);
  for (let t = 0; t < trees.count; t++) if (keep[t]) kept.fill(1, trees.start[t], trees.end[t]);
  keptByScreen.set(flat, { budget, keepPixel, kept });
  return kept;
}

/**
 * The last choice per flattened screen (never changed: a new trace is a new object), so
 * that a choice made ahead, while the view is idle (RayPool.prepareBudget), is not made
 * again by the first edit: for 108,836 rays it took 0.45 s of that step's main thread.
 */
const keptByScreen = new WeakMap<FlatRays, { budget: number; keepPixel: number | null; kept: Uint8Array }>();

/**
 * The trees of a flattened screen as the rule counts them: each sample's root with its
 * subtree, except that a root whose children are a lens's or a shutter's rays (they carry a
 * time, it does not) is a tree alone, the parent of each child's.
 */
function flatTrees(flat: FlatRays): BudgetTrees & { start: Int32Array; end: Int32Array } {
  const start: number[] = [];
  const end: number[] = [];
  const parent: number[] = [];
  const pixel: number[] = [];
  const pixels = flat.pixelStart.length - 1;
  for (let p = 0; p < pixels; p++) {
    for (let root = flat.pixelStart[p]; root < flat.pixelStart[p + 1]; root = flat.subtreeEnd[root]) {
      const rootEnd = flat.subtreeEnd[root];
      const several = flat.time[root] < 0 && root + 1 < rootEnd && flat.time[root + 1] >= 0;
      const rootTree = start.length;
      start.push(root);
      end.push(several ? root + 1 : rootEnd);
      parent.push(-1);
      pixel.push(p);
      if (!several) continue;
      for (let child = root + 1; child < rootEnd; child = flat.subtreeEnd[child]) {
        start.push(child);
        end.push(flat.subtreeEnd[child]);
        parent.push(rootTree);
        pixel.push(p);
      }
    }
  }
  return {
    start: Int32Array.from(start),
    end: Int32Array.from(end),
    count: start.length,
    // A legend entry, drawn as a ray or as a cone.
    kindCount: 2 * RAY_COLOR_KEYS.length,
    size: (t) => end[t] - start[t],
    pixel: (t) => pixel[t],
    parent: (t) => parent[t],
    kinds: (t, visit) => {
      for (let i = start[t]; i < end[t]; i++) visit(flat.colorKey[i] + (flat.cone[i] >= 0 ? RAY_COLOR_KEYS.length : 0));
    },
  };
}

/**
 * What the view says while a budget leaves rays out: the rays drawn (rays plus cones) of the
 * rays the screen traced, whether the view left them out (`thinnedHere`) or the worker
 * already did (its traces say how many they had). Not while a chosen pixel is drawn alone: all
 * of its rays are kept. null: every ray traced is drawn (as the ray panel's rules say). A
 * screen traced from one sample per pixel is told with `before`'s count, the last screen
 * whose rays were all counted.
 */
export function thinningOf(
  rays: ScreenRays | null,
  drawn: DrawnRays,
  thinnedHere: boolean,
  pixelChosen: boolean,
  before: ScreenRays | null = null,
): Thinning | null {
  if (!rays || pixelChosen) return thinnedHere && rays ? thinned(rays, drawn) : null;
  const shown = drawn.rays.count + drawn.cones.count;
  if (!countsEveryRay(rays.traces)) return { shown, of: before && countsEveryRay(before.traces) ? tracedRaysOf(before) : null, oneSample: true };
  return thinnedHere || rays.traces.some((trace) => trace.traced !== undefined) ? thinned(rays, drawn) : null;
}

function thinned(rays: ScreenRays, drawn: DrawnRays): Thinning {
  return { shown: drawn.rays.count + drawn.cones.count, of: tracedRaysOf(rays), oneSample: false };
}

/** The rays `rays` traced, counting those a worker left out. */
function tracedRaysOf(rays: ScreenRays): number {
  let traced = tracedCounts.get(rays);
  if (traced === undefined) tracedCounts.set(rays, (traced = tracedRays(rays.traces)));
  return traced;
}

/** Rays traced per screen (screens are never changed: a new trace is a new object). */
const tracedCounts = new WeakMap<ScreenRays, number>();
