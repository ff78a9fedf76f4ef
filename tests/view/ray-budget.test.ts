import { existsSync, readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { DEFAULT_RAY_VIEW, initialState } from '../../src/lab-state/lab-state.ts';
import { Store } from '../../src/lab-state/store.ts';
import { loadLevels } from '../../src/quest/level-index.ts';
import { newProgress } from '../../src/quest/progress.ts';
import { QuestEngine } from '../../src/quest/quest-engine.ts';
import { DEFAULT_SEED } from '../../src/render/render-job.ts';
import type { ScreenRays } from '../../src/render/screen-rays.ts';
import { loadMeshesFromDisk } from '../../src/scene/load-meshes-node.ts';
import { meshNamesInScene } from '../../src/scene/mesh-names.ts';
import type { Scene } from '../../src/scene/scene.ts';
import type { RayNode } from '../../src/tracer/ray-tree.ts';
import { tracePixels } from '../../src/tracer/trace-pixel.ts';
import { buildTracerScene } from '../../src/tracer/tracer-scene.ts';
import { thinTraces } from '../../src/tracer/tree-budget.ts';
import { EDIT_RAY_BUDGET, editBudgetFor, HEAVY_EDIT_RAYS, keptRays, thinningOf, tracesOneSample } from '../../src/view/ray-budget.ts';
import { flattenRays } from '../../src/view/flat-rays.ts';
import { RAY_COLOR_KEYS } from '../../src/view/ray-palette.ts';
import { type DrawnRays, type SegmentList, visibleRays } from '../../src/view/ray-visibility.ts';
import { FakeClock } from '../support/quest-fixtures.ts';
import { areaRay, ray, screen, syntheticScreen } from '../support/ray-fixtures.ts';

/** The segments of `list` as plain records (what the pool copies into its buffers). */
function records(list: SegmentList) {
  return Array.from({ length: list.count }, (_, j) => ({
    node: list.nodes[j],
    pixel: list.pixel[j],
    key: list.colorKey[j],
    origin: [...list.origin.subarray(j * 3, j * 3 + 3)],
    direction: [...list.direction.subarray(j * 3, j * 3 + 3)],
    color: [...list.color.subarray(j * 3, j * 3 + 3)],
    length: list.length[j],
    radius: list.radius[j],
    alpha: list.alpha[j],
    start: list.start[j],
    corners: list.withCorners ? [...list.corners.subarray(j * 12, j * 12 + 12)] : [],
  }));
}

const drawn = (rays: ScreenRays, selected: [number, number] | null = null): DrawnRays => visibleRays(rays, DEFAULT_RAY_VIEW, selected);
const total = (rays: DrawnRays) => rays.rays.count + rays.cones.count;
/** The rays a screen holds (not those a worker left out). */
const tracedRaysSent = (rays: ScreenRays) => flattenRays(rays).count;

/** `rays` drawn under `budget` as the ray pool draws them while the learner edits; null kept: all. */
function drawnWithin(rays: ScreenRays, budget: number, keepPixel: number | null = null) {
  const kept = keptRays(flattenRays(rays), budget, keepPixel);
  return { kept, drawn: visibleRays(rays, DEFAULT_RAY_VIEW, null, undefined, undefined, true, kept) };
}

/** `rays` as the worker sends it traced from one sample per pixel: each pixel's first root alone, marked. */
function oneSampleScreen(rays: ScreenRays): ScreenRays {
  return { ...rays, traces: rays.traces.map((trace) => ({ ...trace, rays: trace.rays.slice(0, 1), onlySample: 0 })) };
}

/** A pixel sample that casts `lensRays` lens rays from one pinhole ray, each with a light ray. */
function lensSample(lensRays: number): RayNode {
  return ray('primary', {
    length: 5,
    children: Array.from({ length: lensRays }, (_, i) => ray('primary', { time: 0, lensPoint: [i * 0.01, 0, 0], children: [ray('light')] })),
  });
}

describe('keptRays: the rays drawn while the learner edits', () => {
  it('leaves a screen that fits the budget whole', () => {
    const rays = syntheticScreen(800);
    const { kept, drawn: within } = drawnWithin(rays, 1000);
    expect(kept).toBeNull();
    expect(records(within.rays)).toEqual(records(drawn(rays).rays));
  });

  it('keeps about the budget in whole trees, each ray as it is drawn without one, spread over the screen', () => {
    const rays = syntheticScreen(10_000);
    const full = records(drawn(rays).rays);
    const { drawn: within } = drawnWithin(rays, 1000);
    expect(total(within)).toBeGreaterThan(900);
    expect(total(within)).toBeLessThanOrEqual(1000 + 5);
    const kept = records(within.rays);
    // Each kept pixel (one tree of 5 rays here) comes whole, and every segment keeps what it was drawn with.
    const pixels = [...new Set(kept.map((segment) => segment.pixel))];
    expect(kept).toEqual(full.filter((segment) => pixels.includes(segment.pixel)));
    // Every tenth tree or so, over the whole screen.
    const steps = pixels.slice(1).map((p, i) => p - pixels[i]);
    expect(Math.max(...steps)).toBeLessThanOrEqual(11);
    expect(pixels.at(-1)).toBeGreaterThan(1900);
  });

  it('keeps every ray of the chosen pixel', () => {
    const rays = screen(20, 20, () => [lensSample(4), lensSample(4)]);
    const chosen = 7 * 20 + 13;
    const { drawn: within } = drawnWithin(rays, 300, chosen);
    expect(records(within.rays).filter((segment) => segment.pixel === chosen)).toEqual(records(drawn(rays).rays).filter((segment) => segment.pixel === chosen));
  });

  it('keeps lens rays with the pinhole ray they came from, and a tree of every kind drawn', () => {
    const rays = screen(30, 30, (x, y) => [
      x === 29 && y === 29 ? ray('primary', { children: [ray('refract', { hit: false }), areaRay('area-shadow')] }) : lensSample(6),
    ]);
    const { drawn: within } = drawnWithin(rays, 500);
    const kept = records(within.rays);
    expect(total(within)).toBeLessThan(600);
    const keysOf = (segments: ReturnType<typeof records>) => new Set(segments.map((segment) => RAY_COLOR_KEYS[segment.key]));
    expect(keysOf(kept)).toEqual(keysOf(records(drawn(rays).rays)));
    expect(within.cones.count).toBe(1);
    for (const segment of kept) {
      if (segment.node.lensPoint) expect(kept.some((other) => other.node.children.includes(segment.node))).toBe(true);
    }
  });

  it('ends the growth animation where its last kept ray has grown', () => {
    const { drawn: within } = drawnWithin(syntheticScreen(5000), 200);
    const kept = records(within.rays);
    expect(within.travelEnd).toBe(Math.max(...kept.map((segment) => segment.start + segment.length)));
  });

  it('keeps the same rays of the same screen every time', () => {
    const rays = screen(25, 25, (x) => [lensSample(1 + (x % 5))]);
    expect(records(drawnWithin(rays, 400, 3).drawn.rays)).toEqual(records(drawnWithin(rays, 400, 3).drawn.rays));
  });
});

describe('editBudgetFor: how many rays an edited screen is drawn with', () => {
  it('draws a screen within the edit budget whole, and thins a heavier one to a third of it', () => {
    expect(HEAVY_EDIT_RAYS).toBeLessThan(EDIT_RAY_BUDGET);
    const within = syntheticScreen(EDIT_RAY_BUDGET - 5);
    expect(editBudgetFor(within)).toBe(EDIT_RAY_BUDGET);
    expect(keptRays(flattenRays(within), editBudgetFor(within), null)).toBeNull();
    expect(editBudgetFor(null)).toBe(EDIT_RAY_BUDGET);
    const heavy = screen(20, 20, () => [lensSample(5)]);
    expect(editBudgetFor(heavy)).toBe(HEAVY_EDIT_RAYS);
    const { drawn: kept } = drawnWithin(heavy, editBudgetFor(heavy));
    expect(total(kept)).toBeLessThanOrEqual(HEAVY_EDIT_RAYS + 11);
    expect(total(kept)).toBeGreaterThan(HEAVY_EDIT_RAYS - 11);
  });

  it('keeps a screen traced from one sample per pixel heavy, however few rays it sent; only that budget traces so', () => {
    const sampled = oneSampleScreen(syntheticScreen(EDIT_RAY_BUDGET - 5));
    expect(tracedRaysSent(sampled)).toBeLessThan(EDIT_RAY_BUDGET);
    expect(editBudgetFor(sampled)).toBe(HEAVY_EDIT_RAYS);
    expect(tracesOneSample(HEAVY_EDIT_RAYS)).toBe(true);
    expect(tracesOneSample(EDIT_RAY_BUDGET)).toBe(false);
  });

  it('counts the rays a worker left out: a screen it thinned stays heavy', () => {
    const heavy = screen(20, 20, () => [lensSample(5)]);
    const sent: ScreenRays = { ...heavy, traces: thinTraces(heavy.traces, HEAVY_EDIT_RAYS, null) };
    expect(tracedRaysSent(sent)).toBeLessThanOrEqual(EDIT_RAY_BUDGET);
    expect(editBudgetFor(sent)).toBe(HEAVY_EDIT_RAYS);
  });
});

describe('thinningOf: what the view says', () => {
  it('counts the rays drawn of every ray traced, when the view or the worker left some out', () => {
    const rays = screen(10, 10, () => [lensSample(5)]);
    expect(thinningOf(rays, drawn(rays), false, false)).toBeNull();
    const { drawn: within } = drawnWithin(rays, 200);
    expect(thinningOf(rays, within, true, false)).toEqual({ shown: total(within), of: 100 * 11, oneSample: false });
    const sent: ScreenRays = { ...rays, traces: thinTraces(rays.traces, 200, null) };
    const fromSent = drawn(sent);
    expect(thinningOf(sent, fromSent, false, false)).toEqual({ shown: total(fromSent), of: 100 * 11, oneSample: false });
    // A chosen pixel is drawn alone with all its rays: nothing to say.
    expect(thinningOf(sent, drawn(sent, [0, 0]), false, true)).toBeNull();
  });

  it('tells a screen traced from one sample per pixel by the count of the last screen traced whole, before the edit', () => {
    const before = screen(10, 10, () => [lensSample(5), lensSample(5)]);
    const sampled = oneSampleScreen(before);
    const shown = drawn(sampled);
    expect(total(shown)).toBe(100 * 11);
    expect(thinningOf(sampled, shown, false, false, before)).toEqual({ shown: 100 * 11, of: 100 * 22, oneSample: true });
    // No screen counted before (or only another traced from one sample): no count at all.
    expect(thinningOf(sampled, shown, false, false, null)).toEqual({ shown: 100 * 11, of: null, oneSample: true });
    expect(thinningOf(sampled, shown, false, false, sampled)).toEqual({ shown: 100 * 11, of: null, oneSample: true });
    expect(thinningOf(sampled, drawn(sampled, [0, 0]), false, true, before)).toBeNull();
  });
});

describe('the levels’ teaching views', () => {
  it(`draw every ray while the learner edits: no level's screen has more than ${EDIT_RAY_BUDGET}`, async () => {
    const levelsFolder = new URL('../../levels/', import.meta.url);
    const read = (name: string) => (existsSync(new URL(name, levelsFolder)) ? readFileSync(new URL(name, levelsFolder), 'utf8') : undefined);
    const catalog = loadLevels(readFileSync(new URL('index.json', levelsFolder), 'utf8'), read);
    const most: { level: string; rays: number }[] = [];
    for (const [chapter, entry] of catalog.chapters.flatMap((chapter) => chapter.entries.map((entry) => [chapter, entry] as const))) {
      if (!entry.ok) throw new Error(`levels/${entry.id}.level.json is broken`);
      // Every level open, each on its own (as tests/quest/levels-solvable.test.ts plays them).
      const alone = { chapters: [{ ...chapter, entries: [entry] }], errors: [] };
      const engine = new QuestEngine({ catalog: alone, progress: newProgress(new FakeClock()), clock: new FakeClock() });
      const opened = engine.openLevel(entry.level.id);
      if (!opened.ok) throw new Error(opened.reason);
      // The level's scene as it starts, and after each task's solution.
      const store = new Store(initialState(opened.scene));
      const scenes: Scene[] = [opened.scene];
      for (const task of entry.level.tasks) {
        for (const action of task.solution ?? []) store.dispatch(action);
        scenes.push(store.state.scene);
      }
      let rays = 0;
      for (const scene of new Set(scenes)) {
        const tracer = buildTracerScene(scene, await loadMeshesFromDisk(meshNamesInScene(scene)));
        const [columns, rows] = scene.camera.pixels;
        rays = Math.max(rays, total(drawn({ columns, rows, traces: tracePixels(tracer, 0, columns * rows, DEFAULT_SEED) })));
      }
      most.push({ level: entry.level.id, rays });
    }
    expect(most.length).toBeGreaterThanOrEqual(20);
    expect(most.filter(({ rays }) => rays > EDIT_RAY_BUDGET)).toEqual([]);
  }, 120_000);
});
