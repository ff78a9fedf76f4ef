import { describe, expect, it } from 'vitest';
import { INLINE_RAY_BUDGET, InlineScreenTracer } from '../../src/render/inline-screen-tracer.ts';
import { estimateRender } from '../../src/render/render-estimate.ts';
import { DEFAULT_SEED } from '../../src/render/render-job.ts';
import { loadMeshesFromDisk } from '../../src/scene/load-meshes-node.ts';
import { defaultScene } from '../../src/scene/scene-defaults.ts';
import type { Scene } from '../../src/scene/scene.ts';
import { tracePixel } from '../../src/tracer/trace-pixel.ts';
import { buildTracerScene } from '../../src/tracer/tracer-scene.ts';

function sceneWithPixels(columns: number, rows: number): Scene {
  const scene = defaultScene();
  return { ...scene, camera: { ...scene.camera, pixels: [columns, rows] } };
}

/** The default scene with a prism model in front of the camera. */
function sceneWithPrism(): Scene {
  const scene = sceneWithPixels(4, 3);
  return { ...scene, objects: [...scene.objects, { ...scene.objects[1], id: 'prism', shape: 'mesh', mesh: 'prism', position: [0.5, 0.5, 2] }] };
}

/** Idle callbacks that run only when the test says so. */
function manualIdle(): { idle: (callback: () => void) => void; runAll(): void; waiting(): number } {
  const queue: (() => void)[] = [];
  return { idle: (callback) => void queue.push(callback), runAll: () => queue.splice(0).forEach((callback) => callback()), waiting: () => queue.length };
}

describe('InlineScreenTracer', () => {
  it('gives exactly the trees the worker gives: tracePixel with the render seed, models included', async () => {
    const scene = sceneWithPrism();
    const models = await loadMeshesFromDisk(['prism']);
    const rays = new InlineScreenTracer(manualIdle().idle).trace(scene, models);
    const core = buildTracerScene(scene, models);
    expect([rays.columns, rays.rows]).toEqual([4, 3]);
    expect(rays.scene).toBe(scene);
    for (let y = 0; y < 3; y++) {
      for (let x = 0; x < 4; x++) expect(rays.traces[y * 4 + x]).toEqual(tracePixel(core, x, y, DEFAULT_SEED));
    }
    expect(rays.traces.some((trace) => trace.rays[0].children.length > 0)).toBe(true);
  });

  it('traces the ray debugger’s pixel with its terms in the scene it traced last, and says so before any', () => {
    const inline = new InlineScreenTracer(manualIdle().idle);
    expect(() => inline.traceWithTerms(0, 0)).toThrow(/no screen has been traced/);
    const older = sceneWithPixels(4, 3);
    const newer = { ...older, lights: older.lights.map((light) => ({ ...light, intensity: light.intensity / 2 })) };
    inline.trace(older, new Map());
    inline.trace(newer, new Map());
    const terms = inline.traceWithTerms(2, 1);
    expect(terms).toEqual(tracePixel(buildTracerScene(newer, new Map()), 2, 1, DEFAULT_SEED, { terms: true }));
    expect(terms).not.toEqual(tracePixel(buildTracerScene(older, new Map()), 2, 1, DEFAULT_SEED, { terms: true }));
  });

  it('affords a screen within INLINE_RAY_BUDGET estimated rays, and no dearer one', () => {
    const inline = new InlineScreenTracer(manualIdle().idle);
    const lab = sceneWithPixels(16, 16);
    expect(estimateRender(lab, 16, 16).rays).toBeLessThanOrEqual(INLINE_RAY_BUDGET);
    expect(inline.affords(lab, new Map())).toBe(true);
    // Supersampling 2 × 2 makes the same screen four times dearer.
    const supersampled = { ...lab, settings: { ...lab.settings, supersampling: 2 } };
    expect(estimateRender(supersampled, 16, 16).rays).toBeGreaterThan(INLINE_RAY_BUDGET);
    expect(inline.affords(supersampled, new Map())).toBe(false);
  });

  it('affords a scene with a model only once prepare has built its BVH in an idle moment', async () => {
    const idle = manualIdle();
    const inline = new InlineScreenTracer(idle.idle);
    const scene = sceneWithPrism();
    const models = await loadMeshesFromDisk(['prism']);
    expect(inline.affords(scene, new Map())).toBe(false); // the model is not loaded
    expect(inline.affords(scene, models)).toBe(false); // loaded, its BVH not built here
    inline.prepare(models);
    inline.prepare(models);
    expect(idle.waiting()).toBe(1); // one build per model, however often asked
    expect(inline.affords(scene, models)).toBe(false);
    idle.runAll();
    expect(inline.affords(scene, models)).toBe(true);
    inline.prepare(models);
    expect(idle.waiting()).toBe(0);
  });
});
