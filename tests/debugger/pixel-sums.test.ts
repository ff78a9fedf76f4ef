import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { equationAt, equationOf } from '../../src/debugger/debug-equation.ts';
import { debugProgram, type DebugProgram } from '../../src/debugger/debug-steps.ts';
import { initialState } from '../../src/lab-state/lab-state.ts';
import { Store } from '../../src/lab-state/store.ts';
import { loadLevels } from '../../src/quest/level-index.ts';
import type { Level } from '../../src/quest/level-schema.ts';
import { DEFAULT_SEED } from '../../src/render/render-job.ts';
import { loadMeshesFromDisk } from '../../src/scene/load-meshes-node.ts';
import { meshNamesInScene } from '../../src/scene/mesh-names.ts';
import type { Color, Scene } from '../../src/scene/scene.ts';
import { pixelBytes } from '../../src/tracer/quantize.ts';
import type { PixelTrace, RayNode } from '../../src/tracer/ray-tree.ts';
import { renderTile } from '../../src/tracer/render-tile.ts';
import { tracePixel } from '../../src/tracer/trace-pixel.ts';
import { buildTracerScene } from '../../src/tracer/tracer-scene.ts';
import { matte, sceneFrom } from '../support/test-scene.ts';

/**
 * The ray debugger adds every pixel up to the image's colour (issue 37): on every level's
 * starting scene and on each scene its tasks' solutions lead to (where the lens opens, the
 * area light gets samples, the floor turns rough, the ball moves), every pixel of the camera's
 * screen is stepped to the end. Its kind is read off its tree (a lens, time, glossy,
 * area-light, supersampled or plain pixel), and every kind must be met somewhere.
 *
 * For each pixel: the running sum after each step is the sum of what the steps so far
 * added; a ray's steps add exactly its share of the pixel times its colour (so every
 * intermediate sum is a sum of whole shares); the last sum is the image's pixel (rendered
 * apart, as the render window does) to rounding, and the same 8-bit value; an area light's
 * diffuse term only grows, sample by sample, to exactly the tracer's term. A scene with every
 * effect at once (no level has a lens and a shutter together) checks the deepest nesting:
 * sample → lens point → moment → hit.
 */

const levelsFolder = new URL('../../levels/', import.meta.url);
const catalog = loadLevels(readFileSync(new URL('index.json', levelsFolder), 'utf8'), (name) => readFileSync(new URL(name, levelsFolder), 'utf8'));
const levels: Level[] = catalog.chapters.flatMap((chapter) => chapter.entries.flatMap((entry) => (entry.ok ? [entry.level] : [])));

type PixelKind = 'lens' | 'time' | 'glossy' | 'area-light' | 'supersampled' | 'plain';

function walk(nodes: RayNode[], visit: (node: RayNode) => void): void {
  for (const node of nodes) {
    visit(node);
    walk(node.children, visit);
  }
}

/** What kinds of distributed ray a pixel's tree holds (a plain pixel: none of them). */
function kindsOf(trace: PixelTrace, scene: Scene): PixelKind[] {
  const kinds = new Set<PixelKind>();
  if (trace.rays.length > 1) kinds.add('supersampled');
  walk(trace.rays, (node) => {
    if (node.lensPoint && scene.camera.aperture > 0) kinds.add('lens');
    if (node.time !== undefined && scene.settings.timeSamples > 1) {
      const moving = (id: string | null) => scene.objects.some((object) => object.id === id && object.velocity.some((v) => v !== 0));
      let seesMoving = false;
      walk([node], (below) => (seesMoving ||= moving(below.objectId)));
      if (seesMoving) kinds.add('time');
    }
    if (node.glossy) kinds.add('glossy');
    const light = scene.lights.find((candidate) => candidate.id === node.lightId);
    if (light?.type === 'area' && light.samples > 1) kinds.add('area-light');
  });
  return kinds.size === 0 ? ['plain'] : [...kinds];
}

/**
 * The Whitted-mode scenes a level shows: its start, then each new scene its solutions make, in
 * order. A path-mode scene's pixel is the mean of its paths, which the path debugger steps
 * (tests/debugger/path-steps.test.ts), not a ray tree.
 */
function scenesOf(level: Level): Scene[] {
  const store = new Store(initialState(level.scene));
  const scenes = [store.state.scene];
  for (const task of level.tasks) {
    for (const action of task.solution ?? []) {
      store.dispatch(action);
      if (store.state.scene !== scenes.at(-1)) scenes.push(store.state.scene);
    }
  }
  return scenes.filter((scene) => scene.settings.integrator !== 'path');
}

const near = (a: Color, b: Color, tolerance: number) => a.every((value, c) => Math.abs(value - b[c]) <= tolerance);

/** Every step the ray `node` owns: from its cast to its return (or its only step), by index. */
function stepsOfRay(program: DebugProgram, node: RayNode): [number, number] {
  const start = program.steps.findIndex((step) => step.ray === node && (step.kind === 'cast' || step.kind === 'sample'));
  return [start, program.doneAt.get(node) ?? start];
}

function checkPixel(program: DebugProgram, scene: Scene, image: Color): void {
  const { steps, trace } = program;
  // The running sum is what the steps so far added.
  let sum: Color = [0, 0, 0];
  for (const step of steps) {
    sum = [sum[0] + step.adds[0], sum[1] + step.adds[1], sum[2] + step.adds[2]];
    expect(near(step.sum, sum, 1e-12)).toBe(true);
  }
  // A ray's steps add its share of the pixel times its colour: each subtree is a whole share.
  for (const [index, step] of steps.entries()) {
    const ray = step.ray;
    if (!ray || (step.kind !== 'cast' && step.kind !== 'sample') || ray.absorbed) continue;
    const [start, end] = stepsOfRay(program, ray);
    expect(start).toBe(index);
    const before = start > 0 ? steps[start - 1].sum : ([0, 0, 0] as Color);
    const owned = steps[end].sum.map((value, c) => value - before[c]) as Color;
    expect(near(owned, ray.color.map((value) => value * step.share) as Color, 1e-9), `the steps of a ${ray.type} ray add share × its colour`).toBe(true);
  }
  // Only clamping takes anything away, at a return.
  for (const step of steps) {
    if (step.kind === 'return' && step.ray?.terms && step.ray.terms.sum.every((value, c) => value === step.ray!.color[c])) expect(step.adds).toEqual([0, 0, 0]);
    if (step.kind !== 'return') expect(step.adds.every((value) => value >= 0)).toBe(true);
  }
  // The last sum is the image's pixel, to rounding, and the same 8-bit value wherever the value is not on a rounding edge.
  const last = steps.at(-1)!;
  expect(last.kind).toBe('average');
  expect(trace.color).toEqual(image);
  expect(near(last.sum, image, 1e-6)).toBe(true);
  const [x, y] = trace.pixel;
  const onEdge = image.some((value) => Math.abs(((value * 255) % 1) - 0.5) < 1e-4);
  if (!onEdge) expect(pixelBytes(last.sum, x, y, scene.settings)).toEqual(pixelBytes(image, x, y, scene.settings));
  // A light's terms grow with its rays, never shrink, and end at the tracer's own terms.
  for (const step of steps) {
    if (step.kind !== 'return' || !step.ray?.terms) continue;
    const hit = step.ray;
    const lightSteps = steps.flatMap((candidate, index) => (candidate.kind === 'light' && candidate.hit === hit ? [index] : []));
    let previous: Color[] | null = null;
    for (const at of lightSteps) {
      const diffuse = equationAt(program, at, scene)!
        .terms.filter((term) => term.kind === 'diffuse')
        .map((term) => term.color);
      if (previous) for (const [i, color] of diffuse.entries()) expect(color.every((value, c) => value >= previous![i][c])).toBe(true);
      previous = diffuse;
    }
    const final = equationAt(program, steps.indexOf(step), scene)!;
    expect(final.complete).toBe(true);
    const full = equationOf(hit, scene)!;
    expect(final.terms.filter((term) => term.kind === 'diffuse').map((term) => term.color)).toEqual(
      full.terms.filter((term) => term.kind === 'diffuse').map((term) => term.color),
    );
    expect(near(final.sum, full.sum, 1e-12)).toBe(true);
  }
}

/** The tree's shape as the debugger shows it: pixel sample → lens point → moment → hit → its rays, one level deeper each. */
function checkTree(program: DebugProgram): void {
  const samples = program.trace.rays.length;
  for (const [index, step] of program.steps.entries()) {
    if (step.kind === 'average') continue;
    const ray = step.ray;
    if (step.kind === 'sample') {
      expect(step.level).toBe(0);
      expect(step.share).toBe(1 / samples);
    }
    // A lens or time ray under its sample (one lens ray alone is the sample's root: the tree has no extra level).
    if (step.kind === 'cast' && ray?.lensPoint && ray !== program.trace.rays[step.sample]) {
      expect(step.level).toBeGreaterThanOrEqual(1);
      expect(step.share).toBeCloseTo(1 / (samples * program.trace.rays[step.sample].children.length), 15);
      expect(step.place?.of).toMatch(/^(lens|moment)$/);
    }
    // What happens at a hit sits one level under the ray that made it.
    if (step.kind === 'shade' || step.kind === 'light' || step.kind === 'split' || step.kind === 'return') {
      const cast = program.steps.findIndex((candidate) => candidate.kind === 'cast' && candidate.ray === (step.kind === 'light' ? step.hit : step.ray));
      expect(cast).toBeLessThan(index);
      expect(step.level).toBe(program.steps[cast].level + 1);
    }
    if (step.kind === 'light' && step.place) {
      const light = step.hit!.terms!.lights.find((candidate) => candidate.lightId === ray!.lightId)!;
      expect(step.place.count).toBeLessThanOrEqual(light.samples);
    }
  }
}

describe('a pixel with everything at once: supersampled, a lens, a shutter, rough surfaces, an area light', () => {
  const scene = sceneFrom({
    camera: { position: [0, 1.2, 4], target: [0, 0.4, 0], fov: 50, pixels: [6, 4], aperture: 0.1, lensSamples: 2 },
    settings: { maxDepth: 2, background: [0.6, 0.7, 0.9], supersampling: 2, samplePattern: 'jittered', timeSamples: 2 },
    objects: [
      { id: 'floor', shape: 'plane', scale: [10, 1, 10], material: matte([0.8, 0.8, 0.8], { ambient: 0.1, specular: 0.3, roughness: 0.2, glossySamples: 2 }) },
      {
        id: 'ball',
        shape: 'sphere',
        position: [-0.3, 0.5, -0.3],
        velocity: [0.5, 0, 0],
        material: matte([0.9, 0.2, 0.1], { ambient: 0.2, specular: 0.5, roughness: 0.2 }),
      },
    ],
    lights: [{ id: 'panel', type: 'area', position: [0, 3, 0], size: [1, 1], samples: 2, ambient: 0.1 }],
  });
  const tracer = buildTracerScene(scene, new Map());
  const image = renderTile(tracer, { x: 0, y: 0, width: 6, height: 4 }, { imageWidth: 6, imageHeight: 4, seed: DEFAULT_SEED });

  it('nests sample → lens point → moment → hit → its rays, and adds up to the image on every pixel', () => {
    for (let p = 0; p < 24; p++) {
      const program = debugProgram(tracePixel(tracer, p % 6, Math.floor(p / 6), DEFAULT_SEED, { terms: true }), scene);
      checkPixel(program, scene, Array.from(image.subarray(p * 3, p * 3 + 3)) as Color);
      checkTree(program);
      const kinds = (kind: string) => program.steps.filter((step) => step.kind === kind);
      expect(kinds('sample').map((step) => [step.level, step.place])).toEqual([0, 1, 2, 3].map((i) => [0, { of: 'sample', index: i + 1, count: 4 }]));
      expect(kinds('lens').map((step) => [step.level, step.place?.count, step.share])).toEqual(Array(4 * 4).fill([1, 2 * 2, 1 / 16]));
      const moments = kinds('cast').filter((step) => step.ray?.lensPoint);
      expect(moments).toHaveLength(4 * 4 * 2);
      for (const step of moments) expect([step.level, step.place?.of, step.place?.count, step.share]).toEqual([2, 'moment', 2, 1 / 32]);
    }
  });
});

describe('stepping the debugger to the end gives the image’s pixel, on every level', async () => {
  const met = new Set<PixelKind>();
  for (const level of levels.filter((each) => scenesOf(each).length > 0)) {
    it(`${level.id}: every pixel of every scene it shows`, async () => {
      const kinds = new Set<PixelKind>();
      for (const scene of scenesOf(level)) {
        const tracer = buildTracerScene(scene, await loadMeshesFromDisk(meshNamesInScene(scene)));
        const [width, height] = scene.camera.pixels;
        const image = renderTile(tracer, { x: 0, y: 0, width, height }, { imageWidth: width, imageHeight: height, seed: DEFAULT_SEED });
        for (let y = 0; y < height; y++) {
          for (let x = 0; x < width; x++) {
            const trace = tracePixel(tracer, x, y, DEFAULT_SEED, { terms: true });
            const program = debugProgram(trace, scene);
            checkPixel(program, scene, Array.from(image.subarray((y * width + x) * 3, (y * width + x) * 3 + 3)) as Color);
            checkTree(program);
            for (const kind of kindsOf(trace, scene)) kinds.add(kind);
          }
        }
      }
      expect(kinds.size).toBeGreaterThan(0);
      for (const kind of kinds) met.add(kind);
    });
  }
  it('met a pixel of every kind: lens, time, glossy, area-light, supersampled and plain', () => {
    expect([...met].sort()).toEqual(['area-light', 'glossy', 'lens', 'plain', 'supersampled', 'time']);
  });
});
