import { afterAll, describe, expect, it } from 'vitest';
import { pathToFileURL } from 'node:url';
import { RenderPool } from '../../src/render/render-pool.ts';
import type { FinishedRender, RenderImage, RenderProgress, RenderResult } from '../../src/render/render-job.ts';
import { planPasses } from '../../src/render/render-passes.ts';
import { createNodeRenderPool, createNodeWorkerPort } from '../../src/cli/node-worker-port.ts';
import { defaultScene } from '../../src/scene/scene-defaults.ts';
import { emptyRayStats } from '../../src/tracer/ray-tree.ts';
import { renderTile } from '../../src/tracer/render-tile.ts';
import { buildTracerScene } from '../../src/tracer/tracer-scene.ts';
import { sceneFrom } from '../support/test-scene.ts';

const NO_MESHES = new Map();

/** The lab's scene with jittered supersampling and an area light, so every random choice is exercised. */
const scene = sceneFrom({
  ...defaultScene(),
  settings: { ...defaultScene().settings, supersampling: 2, samplePattern: 'jittered' },
  lights: [...defaultScene().lights, { id: 'panel', type: 'area', position: [0, 3, 1], samples: 3 }],
});
/** Not a multiple of the tile size, so the edge tiles are partial. */
const [WIDTH, HEIGHT] = [100, 75];

const pool = createNodeRenderPool(2);
afterAll(() => pool.dispose());

function finished(result: RenderResult): FinishedRender {
  if (result.cancelled) throw new Error('the render was cancelled');
  return result;
}

/** Resolves with the first progress report of a job, when it has really started. */
function firstProgress(): { onProgress: (progress: RenderProgress) => void; started: Promise<void> } {
  let resolveStarted: () => void = () => {};
  const started = new Promise<void>((resolve) => (resolveStarted = resolve));
  return { onProgress: () => resolveStarted(), started };
}

describe('RenderPool with worker threads', () => {
  it('renders exactly the image that one renderTile over the whole image gives', async () => {
    const result = finished(await pool.render(scene, NO_MESHES, { width: WIDTH, height: HEIGHT, seed: 7 }).done);
    const stats = emptyRayStats();
    const whole = renderTile(
      buildTracerScene(scene, NO_MESHES),
      { x: 0, y: 0, width: WIDTH, height: HEIGHT },
      { imageWidth: WIDTH, imageHeight: HEIGHT, seed: 7 },
      stats,
    );

    expect(result).toMatchObject({ width: WIDTH, height: HEIGHT, workers: 2, stats });
    expect(new Uint8Array(result.rgb.buffer)).toEqual(new Uint8Array(whole.buffer));
  });

  it('shows coarse previews, filled in blocks, and a sharp one-sample picture before the final image', async () => {
    const events: string[] = [];
    const previews: RenderImage[] = [];
    const progress: RenderProgress[] = [];
    const job = pool.render(scene, NO_MESHES, {
      width: WIDTH,
      height: HEIGHT,
      onPreview: (image) => {
        events.push('preview');
        previews.push({ ...image, rgb: image.rgb.slice() });
      },
      onProgress: (report) => progress.push(report),
    });
    const result = finished(await job.done);
    events.push('done');

    const passes = planPasses(scene, { width: WIDTH, height: HEIGHT, workers: pool.size, preview: true });
    expect(passes.map((pass) => pass.kind)).toEqual(['preview', 'preview', 'sharp', 'final']);
    expect(events).toEqual([...passes.slice(1).map(() => 'preview'), 'done']);
    // Each coarse preview at its own resolution: pixel (x, y) is block (x, y)'s one sample.
    passes
      .filter((pass) => pass.kind === 'preview')
      .forEach(({ block }, i) => {
        const blocks = renderTile(
          buildTracerScene(scene, NO_MESHES),
          { x: 0, y: 0, width: WIDTH, height: HEIGHT },
          { imageWidth: WIDTH, imageHeight: HEIGHT, seed: 0, block },
        );
        const [width, height] = [Math.ceil(WIDTH / block), Math.ceil(HEIGHT / block)];
        const expected = Array.from({ length: width * height }, (_, p) => [
          ...blocks.slice((Math.floor(p / width) * block * WIDTH + (p % width) * block) * 3).subarray(0, 3),
        ]).flat();
        expect(previews[i]).toMatchObject({ width, height, block });
        expect([...previews[i].rgb]).toEqual(expected);
      });
    // The sharp pass shows the whole image.
    expect([previews.at(-1)!.width, previews.at(-1)!.height]).toEqual([WIDTH, HEIGHT]);
    expect(progress.at(-1)).toMatchObject({ phase: 'final', pass: passes.length, passes: passes.length, done: progress.at(-1)?.total });
    // Progress counts the rays the workers traced: the final pass ends at all of its rays.
    const { primary, shadow, reflect, refract } = result.stats;
    expect(progress.at(-1)?.done).toBe(primary + shadow + reflect + refract);
    expect(job.image.rgb).toBe(result.rgb);
  });

  it('stops a cancelled render, and a render right after completes', async () => {
    const { onProgress, started } = firstProgress();
    let reportsAfterCancel = 0;
    let cancelled = false;
    const big = pool.render(scene, NO_MESHES, {
      width: 640,
      height: 480,
      preview: false,
      onProgress: (report) => {
        onProgress(report);
        if (cancelled) reportsAfterCancel++;
      },
    });
    await started;
    big.cancel();
    cancelled = true;
    expect(await big.done).toEqual({ cancelled: true });

    const next = await pool.render(scene, NO_MESHES, { width: 40, height: 30 }).done;
    expect(next).toMatchObject({ cancelled: false, width: 40, height: 30 });
    expect(reportsAfterCancel).toBe(0);
  });

  it('traces a camera pixel to exactly the colour an image at camera.pixels resolution has there', async () => {
    const [columns, rows] = scene.camera.pixels;
    const image = finished(await pool.render(scene, NO_MESHES, { width: columns, height: rows, seed: 3 }).done);
    const trace = await pool.tracePixel(5, 2, 3);

    expect(trace.pixel).toEqual([5, 2]);
    expect(trace.rays).toHaveLength(4); // 2×2 supersamples
    const at = (2 * columns + 5) * 3;
    expect(trace.color).toEqual([...image.rgb.slice(at, at + 3)]);
  });

  it('traces a pixel with its shading terms on request (the ray debugger), the same rays and colour', async () => {
    pool.setScene(scene, NO_MESHES);
    // The bottom row sees the floor.
    const [, rows] = scene.camera.pixels;
    const plain = await pool.tracePixel(2, rows - 1, 3);
    const withTerms = await pool.tracePixel(2, rows - 1, 3, true);

    expect(plain.rays[0].terms).toBeUndefined();
    expect(withTerms.color).toEqual(plain.color);
    expect(withTerms.rays[0].hit).toBe(true);
    expect(withTerms.rays[0].terms?.lights.map((light) => light.lightId)).toEqual(scene.lights.map((light) => light.id));
  });

  it('rejects a job whose scene the workers cannot build, with the reason, and renders again', async () => {
    const withMesh = sceneFrom({ objects: [{ id: 'gem', shape: 'mesh', mesh: 'prism' }] });
    await expect(pool.render(withMesh, NO_MESHES, { width: 20, height: 20 }).done).rejects.toThrow(/prism/);
    await expect(pool.ready()).rejects.toThrow(/prism/);

    const next = await pool.render(scene, NO_MESHES, { width: 20, height: 20 }).done;
    expect(next.cancelled).toBe(false);
  });

  it('replaces a worker that dies and completes the job', async () => {
    const crashing = pathToFileURL(new URL('../support/crashing-worker.ts', import.meta.url).pathname).href;
    let started = 0;
    // The first worker crashes on its first message; the second and the replacement work.
    const flaky = new RenderPool({
      size: 2,
      log: () => {},
      createWorker: (handlers) => (started++ === 0 ? createNodeWorkerPort(handlers, crashing) : createNodeWorkerPort(handlers)),
    });
    try {
      const next = await flaky.render(scene, NO_MESHES, { width: 20, height: 20 }).done;
      expect(next).toMatchObject({ cancelled: false, width: 20, height: 20 });
      expect(started).toBe(3);
    } finally {
      flaky.dispose();
    }
  });
});
