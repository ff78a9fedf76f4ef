import { describe, expect, it } from 'vitest';
import { meanOfPaths, pathRows, type PathVertexRow } from '../../src/debugger/path-steps.ts';
import { labPaths } from '../../src/tracer/lab-paths.ts';
import type { TracerScene } from '../../src/tracer/tracer-scene.ts';
import { matte, tracerSceneFrom } from '../support/test-scene.ts';

const ALBEDO: Record<string, [number, number, number]> = { floor: [0.7, 0.7, 0.7], back: [0.7, 0.7, 0.7], left: [0.7, 0.1, 0.1], ball: [0.5, 0.6, 0.2] };

/** A small open room lit by an area light, every surface matte (so f = albedo/π everywhere). */
function room(settings: Record<string, unknown>): TracerScene {
  const wall = (id: string, position: number[], rotation: number[]) => ({
    id,
    shape: 'plane',
    position,
    rotation,
    scale: [2, 1, 2],
    material: matte(ALBEDO[id]!),
  });
  return tracerSceneFrom({
    camera: { position: [0, 1, 3.5], target: [0, 0.6, 0], fov: 45, pixels: [4, 4] },
    settings: { integrator: 'path', background: [0.2, 0.3, 0.4], maxDepth: 6, pathSamples: 64, ...settings },
    objects: [
      wall('floor', [0, 0, 0], [0, 0, 0]),
      wall('back', [0, 1, -1], [90, 0, 0]),
      wall('left', [-1, 1, 0], [0, 0, -90]),
      { id: 'ball', shape: 'sphere', position: [0.2, 0.4, 0], scale: [0.4, 0.4, 0.4], material: matte(ALBEDO.ball!) },
    ],
    lights: [{ id: 'panel', type: 'area', position: [0, 1.99, 0], size: [0.6, 0.6], color: [1, 1, 1], intensity: 8, samples: 1 }],
  });
}

const STRATEGIES = [
  { bounceSampling: 'cosine', lightSampling: true, russianRoulette: false },
  { bounceSampling: 'uniform', lightSampling: false, russianRoulette: true },
  { bounceSampling: 'cosine', lightSampling: true, russianRoulette: true },
];

function expectColor(actual: readonly number[], expected: readonly number[], digits = 12): void {
  for (let c = 0; c < 3; c++) expect(actual[c]).toBeCloseTo(expected[c]!, digits);
}

describe('the path debugger’s numbers, against the recorded paths', () => {
  for (const strategy of STRATEGIES) {
    const name = `${strategy.bounceSampling} bounces, light sampling ${strategy.lightSampling}, roulette ${strategy.russianRoulette}`;
    const scene = room(strategy);
    const pixels = [
      [1, 2],
      [2, 3],
      [0, 1],
    ] as const;
    const traced = pixels.map(([x, y]) => labPaths(scene, x, y, 3, 64));
    const rowsOf = traced.flatMap((paths) => paths.paths.map((path) => ({ path, rows: pathRows(path, strategy) })));

    it(`${name}: the listed paths' contributions average to the pixel, to the last bit`, () => {
      for (const paths of traced) {
        expect(paths.contributions).toHaveLength(64);
        expect(paths.paths.map((path) => path.contribution)).toEqual(paths.contributions.slice(0, paths.paths.length));
        expect(meanOfPaths(paths.contributions)).toEqual(paths.color);
      }
      // Not all black: the numbers below are about light that arrived.
      expect(traced.some((paths) => paths.color.some((c) => c > 0))).toBe(true);
    });

    it(`${name}: each path's running sum ends at its contribution, made of its light samples and what it saw directly`, () => {
      for (const { path, rows } of rowsOf) {
        expect(rows.at(-1)!.runningSum).toEqual(path.contribution);
        const parts = rows.reduce(
          (sum, row) =>
            row.lightSamples.reduce(
              (inner, sample) => inner.map((v, c) => v + sample.added[c]!),
              sum.map((v, c) => v + row.emitted[c]!),
            ),
          [0, 0, 0],
        );
        expectColor(parts, path.contribution);
        // Only the last vertex sees light directly; the sum never goes down.
        rows.slice(0, -1).forEach((row) => expect(row.emitted).toEqual([0, 0, 0]));
      }
    });

    it(`${name}: a diffuse vertex multiplies the throughput by albedo/π · cosθ / pdf`, () => {
      let diffuse = 0;
      for (const { rows } of rowsOf) {
        rows.forEach((row: PathVertexRow) => {
          if (row.event !== 'diffuse') return;
          diffuse++;
          const albedo = ALBEDO[row.objectId!]!;
          expect(row.cosTheta!).toBeGreaterThan(0);
          expect(row.pdf).toBeCloseTo(strategy.bounceSampling === 'uniform' ? 1 / (2 * Math.PI) : row.cosTheta! / Math.PI, 12);
          expectColor(
            row.factor!,
            albedo.map((a) => (a / Math.PI) * (row.cosTheta! / row.pdf!)),
          );
        });
      }
      expect(diffuse).toBeGreaterThan(50);
    });

    it(`${name}: the throughput so far is the product of the factors, over the roulette's chances`, () => {
      let survived = 0;
      for (const { rows } of rowsOf) {
        let product = [1, 1, 1];
        for (const row of rows) {
          if (row.factor) product = product.map((p, c) => p * row.factor![c]!);
          if (row.survival !== null) {
            survived++;
            product = product.map((p) => p / row.survival!);
          }
          if (row.factor || row.survival !== null) expectColor(row.throughput, product);
        }
      }
      if (strategy.russianRoulette) expect(survived).toBeGreaterThan(0);
      else expect(survived).toBe(0);
    });

    it(`${name}: each light sample is taken at its own vertex, toward the light above the surface`, () => {
      let samples = 0;
      for (const { path } of rowsOf) {
        expect(path.vertices[0]!.lightSamples).toEqual([]);
        for (const vertex of path.vertices) {
          for (const sample of vertex.lightSamples) {
            samples++;
            expect(vertex.event).toBe('diffuse');
            const toLight = sample.target.map((t, c) => t - vertex.point[c]!);
            expect(toLight.reduce((sum, t, c) => sum + t * vertex.normal![c]!, 0)).toBeGreaterThan(0);
          }
        }
      }
      if (strategy.lightSampling) expect(samples).toBeGreaterThan(20);
      else expect(samples).toBe(0);
    });
  }
});
