import { Vector3 } from 'three';
import { describe, expect, it } from 'vitest';
import { PathRecorder } from '../../src/tracer/path-recorder.ts';
import { renderPathPixel } from '../../src/tracer/render-path-pixel.ts';
import { renderPixel } from '../../src/tracer/render-pixel.ts';
import type { TracerScene } from '../../src/tracer/tracer-scene.ts';
import { matte, pointLight, tracerSceneFrom } from '../support/test-scene.ts';

const CAMERA = { position: [0, 0, 5], target: [0, 0, 0], fov: 30, pixels: [8, 8] };

/** A diffuse ball of albedo ρ alone in a uniform environment of radiance L ("the furnace"). */
function furnace(albedo: number, settings: Record<string, unknown>): TracerScene {
  return tracerSceneFrom({
    camera: CAMERA,
    settings: { integrator: 'path', background: [0.5, 0.5, 0.5], maxDepth: 4, ...settings },
    objects: [{ id: 'ball', shape: 'sphere', material: matte([albedo, albedo, albedo]) }],
    lights: [],
  });
}

/** Every path of pixel (x, y) of a width × height image: their contributions, and the pixel. */
function paths(scene: TracerScene, x: number, y: number, size: number, seed = 1) {
  const recorder = new PathRecorder();
  const pixel = renderPathPixel(scene, x, y, size, size, seed, new Vector3(), recorder);
  return { recorder, pixel };
}

/** Mean and standard error of the mean of each channel of the paths' contributions. */
function estimate(recorder: PathRecorder): { mean: number[]; error: number[] } {
  const n = recorder.paths.length;
  const mean = [0, 1, 2].map((c) => recorder.paths.reduce((sum, path) => sum + path.contribution[c]!, 0) / n);
  const error = [0, 1, 2].map((c) => Math.sqrt(recorder.paths.reduce((sum, path) => sum + (path.contribution[c]! - mean[c]!) ** 2, 0) / (n - 1) / n));
  return { mean, error };
}

describe('path mode: the furnace test', () => {
  it('shows exactly ρ·L on a diffuse ball in a uniform environment with cosine bounces', () => {
    // Each path: the ball, one cosine-sampled bounce (f·cosθ/pdf = ρ), then the environment.
    const scene = furnace(0.6, { bounceSampling: 'cosine', pathSamples: 16 });
    const { pixel } = paths(scene, 32, 32, 64);
    expect(pixel.x).toBeCloseTo(0.3, 12);
  });

  it('converges to ρ·L with uniform bounces, within the noise it measures itself', () => {
    const scene = furnace(0.6, { bounceSampling: 'uniform', pathSamples: 4096 });
    const { recorder } = paths(scene, 32, 32, 64);
    const { mean, error } = estimate(recorder);
    expect(error[0]).toBeGreaterThan(0);
    expect(Math.abs(mean[0]! - 0.3)).toBeLessThan(4 * error[0]!);
  });

  it('sees the environment itself beside the ball', () => {
    const { pixel } = paths(furnace(0.6, {}), 0, 0, 64);
    expect(pixel.toArray()).toEqual([0.5, 0.5, 0.5]);
  });
});

describe('path mode: a point light with 1/d²', () => {
  it('lights a floor straight below it with ρ/π · I/h², with direct light only', () => {
    // A camera looking straight down at the floor, the light 2 m above the point seen.
    const scene = tracerSceneFrom({
      camera: { position: [0, 3, 0.001], target: [0, 0, 0], fov: 1, pixels: [1, 1] },
      settings: { integrator: 'path', background: [0, 0, 0], maxDepth: 0, pathSamples: 64 },
      objects: [{ id: 'floor', shape: 'plane', scale: [10, 1, 10], material: matte([0.8, 0.8, 0.8]) }],
      lights: [pointLight([0, 2, 0], { intensity: 3 })],
    });
    const pixel = renderPathPixel(scene, 0, 0, 1, 1, 1, new Vector3(), null);
    expect(pixel.x).toBeCloseTo((0.8 / Math.PI) * (3 / 4), 4);
  });
});

/** A small closed room: an area light in the ceiling, coloured walls, a mirror ball and a glass ball. */
function room(settings: Record<string, unknown>): TracerScene {
  const wall = (id: string, position: number[], rotation: number[], color: [number, number, number]) => ({
    id,
    shape: 'plane',
    position,
    rotation,
    scale: [2, 1, 2],
    material: matte(color),
  });
  return tracerSceneFrom({
    camera: { position: [0, 1, 3.5], target: [0, 1, 0], fov: 45, pixels: [4, 4] },
    settings: { integrator: 'path', background: [0, 0, 0], maxDepth: 5, ...settings },
    objects: [
      wall('floor', [0, 0, 0], [0, 0, 0], [0.7, 0.7, 0.7]),
      wall('ceiling', [0, 2, 0], [180, 0, 0], [0.7, 0.7, 0.7]),
      wall('back', [0, 1, -1], [90, 0, 0], [0.7, 0.7, 0.7]),
      wall('left', [-1, 1, 0], [0, 0, -90], [0.7, 0.1, 0.1]),
      wall('right', [1, 1, 0], [0, 0, 90], [0.1, 0.7, 0.1]),
      { id: 'mirror', shape: 'sphere', position: [-0.4, 0.3, -0.3], scale: [0.3, 0.3, 0.3], material: matte([0.2, 0.2, 0.2], { specular: 0.8 }) },
      {
        id: 'glass',
        shape: 'sphere',
        position: [0.4, 0.3, 0.2],
        scale: [0.3, 0.3, 0.3],
        material: matte([1, 1, 1], { transparent: true, refractiveIndex: 1.5 }),
      },
    ],
    lights: [{ id: 'panel', type: 'area', position: [0, 1.99, 0], size: [0.6, 0.6], color: [1, 1, 1], intensity: 8, samples: 1 }],
  });
}

describe('path mode: every strategy has the same expected picture', () => {
  const combinations = ['cosine', 'uniform'].flatMap((bounceSampling) =>
    [true, false].flatMap((lightSampling) => [false, true].map((russianRoulette) => ({ bounceSampling, lightSampling, russianRoulette }))),
  );
  // Pixels of the small screen: the floor under the ball, the red wall, the mirror ball, the glass ball.
  const pixelsToCheck = [
    [3, 6],
    [0, 4],
    [2, 6],
    [5, 6],
  ] as const;
  const reference = pixelsToCheck.map(([x, y]) => estimate(paths(room({ pathSamples: 4000, lightSampling: true }), x, y, 8).recorder));

  for (const strategy of combinations) {
    it(`${strategy.bounceSampling} bounces, light sampling ${strategy.lightSampling ? 'on' : 'off'}, Russian roulette ${strategy.russianRoulette ? 'on' : 'off'}`, () => {
      const scene = room({ pathSamples: 4000, ...strategy });
      pixelsToCheck.forEach(([x, y], index) => {
        const { mean, error } = estimate(paths(scene, x, y, 8, 7).recorder);
        for (let c = 0; c < 3; c++) {
          // Two independent estimates of one value: their difference is within 4.5 joint standard errors.
          const joint = Math.hypot(error[c]!, reference[index]!.error[c]!);
          expect(Math.abs(mean[c]! - reference[index]!.mean[c]!), `pixel ${x},${y} channel ${c}`).toBeLessThan(4.5 * joint + 1e-9);
        }
      });
    });
  }
});

describe('path mode: Russian roulette', () => {
  it('lets a path of largest throughput β < 1 go on with chance √β, as Cycles does', () => {
    // Uniform bounces and no light sampling: throughputs spread widely below 1. Over every
    // vertex that faced the roulette, the paths it stopped number Σ(1 − √β) within the binomial
    // noise; pbrt-v4's chance β would stop Σ(1 − β), many more.
    const { recorder } = paths(room({ pathSamples: 4000, russianRoulette: true, bounceSampling: 'uniform', lightSampling: false }), 3, 6, 8);
    let stopped = 0;
    let expected = 0;
    let variance = 0;
    let expectedByBeta = 0;
    for (const { vertices } of recorder.paths) {
      vertices.forEach((vertex, i) => {
        const largest = Math.max(...vertex.throughput);
        if (i < 2 || vertex.direction === null || largest >= 1) return;
        const survival = Math.sqrt(largest);
        expected += 1 - survival;
        variance += survival * (1 - survival);
        expectedByBeta += 1 - largest;
        if (vertices[i + 1]!.event === 'roulette-stop') stopped++;
      });
    }
    expect(expected).toBeGreaterThan(500);
    expect(Math.abs(stopped - expected)).toBeLessThan(4 * Math.sqrt(variance));
    expect(expectedByBeta - expected).toBeGreaterThan(10 * Math.sqrt(variance));
  });
});

describe('path mode: recorded paths', () => {
  it('average to the rendered pixel to the last bit', () => {
    const scene = room({ pathSamples: 32, russianRoulette: true });
    const rendered = renderPixel(scene, 3, 6, 8, 8, 11, new Vector3(), null);
    const { recorder } = paths(scene, 3, 6, 8, 11);
    const sum = new Vector3();
    for (const path of recorder.paths) sum.add(new Vector3(...path.contribution));
    expect(sum.divideScalar(recorder.paths.length).toArray()).toEqual(rendered.toArray());
  });

  it('start at the camera and end in one of the stated ways', () => {
    const { recorder } = paths(room({ pathSamples: 1000, russianRoulette: true }), 3, 6, 8);
    const ends = new Set(recorder.paths.map((path) => path.vertices.at(-1)!.event));
    for (const path of recorder.paths) expect(path.vertices[0]!.event).toBe('camera');
    for (const end of ends) expect(['emitter', 'escaped', 'roulette-stop', 'max-depth', 'absorbed']).toContain(end);
    expect([...ends].sort()).toEqual(['emitter', 'escaped', 'max-depth', 'roulette-stop']);
  });
});

describe('path mode: a pixel of the camera screen traced again', () => {
  it('has the colour of that pixel in the image of camera.pixels, and hands back the first K paths', async () => {
    const { tracePaths } = await import('../../src/tracer/trace-paths.ts');
    const { renderTile } = await import('../../src/tracer/render-tile.ts');
    const scene = room({ pathSamples: 24 });
    const image = renderTile(scene, { x: 0, y: 0, width: 4, height: 4 }, { imageWidth: 4, imageHeight: 4, seed: 3 });
    const traced = tracePaths(scene, 1, 2, 3, 5);
    const at = (2 * 4 + 1) * 3;
    expect(traced.color).toEqual([image[at], image[at + 1], image[at + 2]]);
    expect(traced.pathCount).toBe(24);
    expect(traced.paths).toHaveLength(5);
  });
});
