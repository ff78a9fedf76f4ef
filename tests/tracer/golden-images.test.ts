import { existsSync, readFileSync, writeFileSync } from 'node:fs';
import { PNG } from 'pngjs';
import { describe, expect, it } from 'vitest';
import { loadMeshesFromDisk } from '../../src/scene/load-meshes-node.ts';
import { meshNamesInScene } from '../../src/scene/mesh-names.ts';
import type { Scene } from '../../src/scene/scene.ts';
import { defaultScene } from '../../src/scene/scene-defaults.ts';
import { toRgba8 } from '../../src/tracer/quantize.ts';
import { renderTile } from '../../src/tracer/render-tile.ts';
import { buildTracerScene } from '../../src/tracer/tracer-scene.ts';
import { sceneFrom } from '../support/test-scene.ts';

/**
 * Whole-pipeline regression: small renders compared with reviewed PNGs in tests/golden.
 * After an intended change, look at the new images, then: UPDATE_GOLDEN=1 npx vitest run tests/tracer/golden-images.test.ts
 */
const WIDTH = 128;
const HEIGHT = 96;
// Math.pow/sin/cos may differ in the last bit between CPUs or V8 versions: allow a stray
// off-by-one level, but nothing a person could see.
const MAX_LEVEL_DIFFERENCE = 1;
const MAX_DIFFERING_SHARE = 0.002;

const softShadows = (): Scene =>
  sceneFrom({
    camera: { position: [0, 2.2, 4.5], target: [0, 0.3, 0], fov: 45 },
    settings: { supersampling: 2, samplePattern: 'jittered', background: [0.1, 0.1, 0.15] },
    objects: [
      { id: 'floor', shape: 'plane', scale: [8, 1, 8], material: { color: [0.9, 0.9, 0.9] } },
      { id: 'pillar', shape: 'cylinder', position: [-0.7, 0.5, 0], material: { color: [0.9, 0.5, 0.2] } },
      { id: 'cube', shape: 'box', position: [0.8, 0.3, 0.3], rotation: [0, 45, 0], scale: [0.6, 0.6, 0.6], material: { color: [0.3, 0.6, 0.9] } },
    ],
    lights: [
      { id: 'disc', type: 'area', shape: 'disc', position: [0, 2.5, 0], size: [1.5, 1.5], samples: 5, intensity: 0.9 },
      { id: 'spot', type: 'spot', position: [2, 2.5, 1], rotation: [0, 0, 35], spotAngle: 50, angleAttenuation: 2, intensity: 0.6, distanceAttenuation: true },
    ],
  });

// Models float 2 mm above the floor: faces exactly in the floor's plane would speckle (z-fighting).
const glassModels = (): Scene =>
  sceneFrom({
    camera: { position: [0, 1, 3.2], target: [0, 0.45, 0], fov: 40 },
    settings: { maxDepth: 5, background: [0.75, 0.8, 0.9] },
    objects: [
      { id: 'floor', shape: 'plane', scale: [8, 1, 8], material: { color: [0.6, 0.6, 0.6] } },
      { id: 'wall', shape: 'plane', position: [0, 1.5, -1.5], rotation: [90, 0, 0], scale: [8, 1, 3], material: { color: [0.9, 0.3, 0.3] } },
      {
        id: 'glass',
        shape: 'mesh',
        mesh: 'wine-glass',
        position: [-0.6, 0.502, 0],
        material: { ambient: 0, diffuse: 0, transparent: true, refractiveIndex: 1.5 },
      },
      {
        id: 'prism',
        shape: 'mesh',
        mesh: 'prism',
        position: [0.2, 0.302, 0.3],
        scale: [0.6, 0.6, 0.6],
        material: { color: [0.8, 1, 0.8], diffuse: 0.1, transparent: true },
      },
      { id: 'robot', shape: 'mesh', mesh: 'character', position: [0.9, 0.5, -0.4], material: { color: [0.9, 0.8, 0.5], specular: 0.3 } },
    ],
    lights: [{ id: 'lamp', type: 'point', position: [1, 3, 2] }],
  });

/** Four balls from near to far, the second (at the target) in focus (distribution-effects §2, the lens). */
const depthOfField = (): Scene =>
  sceneFrom({
    camera: { position: [0, 0.9, 4], target: [0, 0.5, 0], fov: 40, aperture: 0.12, lensSamples: 4 },
    settings: { background: [0.75, 0.8, 0.9] },
    objects: [
      { id: 'floor', shape: 'plane', scale: [12, 1, 20], material: { color: [0.8, 0.8, 0.7] } },
      ...[-1, 0, 1, 2].map((step) => ({
        id: `ball${step + 1}`,
        shape: 'sphere',
        position: [step * 0.7, 0.4, -step * 1.6],
        scale: [0.8, 0.8, 0.8],
        material: { color: [0.3 + 0.2 * (step + 1), 0.3, 0.9 - 0.2 * (step + 1)] },
      })),
    ],
    lights: [{ id: 'lamp', type: 'point', position: [2, 4, 3] }],
  });

/** A brushed-metal floor, a rough metal ball and a frosted glass ball (the glossy spread). */
const glossy = (): Scene =>
  sceneFrom({
    camera: { position: [0, 1.1, 3.6], target: [0, 0.4, 0], fov: 45 },
    settings: { maxDepth: 2, background: [0.5, 0.6, 0.8] },
    objects: [
      { id: 'floor', shape: 'plane', scale: [10, 1, 10], material: { color: [0.3, 0.3, 0.3], diffuse: 0.4, specular: 0.6, roughness: 0.12 } },
      { id: 'red', shape: 'box', position: [-1.3, 0.4, -1], rotation: [0, 30, 0], scale: [0.8, 0.8, 0.8], material: { color: [0.9, 0.2, 0.1] } },
      { id: 'metal', shape: 'sphere', position: [0.1, 0.5, -0.4], material: { color: [0.9, 0.8, 0.5], diffuse: 0.2, specular: 0.8, roughness: 0.3 } },
      {
        id: 'frosted',
        shape: 'sphere',
        position: [1.2, 0.4, 0.5],
        scale: [0.8, 0.8, 0.8],
        material: { ambient: 0, diffuse: 0.05, transparent: true, roughness: 0.25, glossySamples: 2 },
      },
    ],
    lights: [{ id: 'lamp', type: 'point', position: [2, 4, 3] }],
  });

/** A ball moving sideways past a still box, the shutter open for 8 times per sample (motion blur). */
const motionBlur = (): Scene =>
  sceneFrom({
    camera: { position: [0, 1, 4], target: [0, 0.5, 0], fov: 40 },
    settings: { timeSamples: 8, background: [0.85, 0.85, 0.8] },
    objects: [
      { id: 'floor', shape: 'plane', scale: [10, 1, 10], material: { color: [0.6, 0.7, 0.6] } },
      { id: 'box', shape: 'box', position: [0.9, 0.4, -0.6], scale: [0.8, 0.8, 0.8], material: { color: [0.2, 0.4, 0.9] } },
      { id: 'ball', shape: 'sphere', position: [-1.4, 0.5, 0.3], velocity: [1.4, 0, 0], material: { color: [0.9, 0.3, 0.1] } },
    ],
    lights: [{ id: 'lamp', type: 'point', position: [1, 4, 3] }],
  });

const cases: [string, () => Scene][] = [
  ['default-scene', defaultScene],
  ['soft-shadows', softShadows],
  ['glass-models', glassModels],
  ['depth-of-field', depthOfField],
  ['glossy', glossy],
  ['motion-blur', motionBlur],
];

async function render(scene: Scene): Promise<Uint8ClampedArray> {
  const tracer = buildTracerScene(scene, await loadMeshesFromDisk(meshNamesInScene(scene)));
  const rgb = renderTile(tracer, { x: 0, y: 0, width: WIDTH, height: HEIGHT }, { imageWidth: WIDTH, imageHeight: HEIGHT, seed: 1 });
  return toRgba8(rgb, WIDTH, HEIGHT, scene.settings);
}

describe('golden images', () => {
  for (const [name, makeScene] of cases) {
    it(`${name} renders as reviewed`, async () => {
      const actual = await render(makeScene());
      const path = new URL(`../golden/${name}.png`, import.meta.url);
      if (process.env.UPDATE_GOLDEN || !existsSync(path)) {
        const png = new PNG({ width: WIDTH, height: HEIGHT });
        png.data = Buffer.from(actual);
        writeFileSync(path, PNG.sync.write(png));
        if (!process.env.UPDATE_GOLDEN) throw new Error(`no golden image yet: wrote ${path.pathname}; review it and commit it`);
      }
      const expected = PNG.sync.read(readFileSync(path));
      expect([expected.width, expected.height]).toEqual([WIDTH, HEIGHT]);
      let differing = 0;
      let worst = 0;
      for (let i = 0; i < actual.length; i++) {
        const difference = Math.abs(actual[i] - expected.data[i]);
        worst = Math.max(worst, difference);
        if (difference > 0) differing++;
      }
      expect(worst).toBeLessThanOrEqual(MAX_LEVEL_DIFFERENCE);
      expect(differing / actual.length).toBeLessThanOrEqual(MAX_DIFFERING_SHARE);
    });
  }
});
