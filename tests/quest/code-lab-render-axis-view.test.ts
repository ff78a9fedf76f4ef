import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import type { LabOutcome } from '../../src/quest/code-labs/code-lab-grading.ts';
import { topDownCamera } from '../../src/quest/code-labs/lab-render/axis-view.ts';
import type { LabCamera } from '../../src/quest/code-labs/lab-render/lab-camera.ts';
import { labRenderScene } from '../../src/quest/code-labs/lab-render/lab-render-scene.ts';
import { pictureDifference } from '../../src/quest/code-labs/lab-render/picture-difference.ts';
import { renderWithLearner } from '../../src/quest/code-labs/lab-render/render-passes.ts';
import { RAY_BOX_TOLERANCE } from '../../src/quest/code-labs/ray-box-lab.ts';
import { parseLevelJson } from '../../src/quest/level-schema.ts';
import { toRgba8 } from '../../src/tracer/quantize.ts';
import { slabTest, type HitBox, type SlabMistakes } from '../support/slab-tests.ts';

/*
 * The box lab's second view: level 15 seen from straight above, every ray along −y. A slab
 * test broken only for rays parallel to a slab renders the level's own view like a correct
 * one (none of its rays has a zero component) but not this one.
 */

const WIDTH = 160;
const HEIGHT = 120;

const parsed = parseLevelJson(readFileSync(new URL('../../levels/15-bounding-boxes.level.json', import.meta.url), 'utf8'));
if (!parsed.ok) throw new Error('level 15 does not parse');
const scene = labRenderScene(parsed.level.scene);

/** Renders level 15 with `hitBox` as the sandbox would run it; the pixels that differ from the reference, or why there is no picture. */
async function differing(hitBox: HitBox, camera?: LabCamera) {
  const result = await renderWithLearner(
    scene,
    'ray-box',
    RAY_BOX_TOLERANCE,
    (calls) => {
      const outcomes = calls.map((args): LabOutcome => ({ returned: hitBox(...(structuredClone(args) as Parameters<HitBox>)) }));
      return Promise.resolve({ outcomes });
    },
    WIDTH,
    HEIGHT,
    camera,
  );
  if (result.kind !== 'rendered') return result.kind;
  const bytes = (rgb: Float32Array) => toRgba8(rgb, WIDTH, HEIGHT, scene.source.settings);
  return pictureDifference(bytes(result.mine), bytes(result.reference)).differing;
}

describe('the box lab’s view from straight above', () => {
  const camera = topDownCamera(scene);

  it('sends every ray straight down from above the shapes, parallel to the x and z slabs', () => {
    const top = Math.max(...scene.boxes.map(({ max }) => max.y), ...scene.spheres.map(({ center, radius }) => center.y + radius));
    for (const [x, y] of [
      [0.5, 0.5],
      [80, 60],
      [159.5, 119.5],
    ] as const) {
      const { origin, direction } = camera(x, y, WIDTH, HEIGHT);
      expect(direction).toEqual({ x: 0, y: -1, z: 0 });
      expect(origin.y).toBeGreaterThan(top);
    }
    // x to the right, −z (away from the level's camera) up; the picture keeps its aspect (square pixels).
    const corner = camera(0, 0, WIDTH, HEIGHT).origin;
    const across = camera(WIDTH, 0, WIDTH, HEIGHT).origin;
    const down = camera(0, HEIGHT, WIDTH, HEIGHT).origin;
    expect(across.x).toBeGreaterThan(corner.x);
    expect(down.z).toBeGreaterThan(corner.z);
    expect((across.x - corner.x) / WIDTH).toBeCloseTo((down.z - corner.z) / HEIGHT, 12);
  });

  it('frames every box and sphere of the level', () => {
    const corner = camera(0, 0, WIDTH, HEIGHT).origin;
    const opposite = camera(WIDTH, HEIGHT, WIDTH, HEIGHT).origin;
    for (const { min, max } of scene.boxes) {
      expect(min.x).toBeGreaterThan(corner.x);
      expect(max.x).toBeLessThan(opposite.x);
      expect(min.z).toBeGreaterThan(corner.z);
      expect(max.z).toBeLessThan(opposite.z);
    }
    for (const { center, radius } of scene.spheres) {
      expect(center.x - radius).toBeGreaterThan(corner.x);
      expect(center.x + radius).toBeLessThan(opposite.x);
    }
  });

  it('renders a correct slab test exactly as the reference', async () => {
    expect(await differing(slabTest(), camera)).toBe(0);
  });

  it.each<[string, SlabMistakes]>([
    ['parallel rays made to miss', { parallelMisses: true }],
    ['the parallel slabs skipped', { parallelIgnored: true }],
  ])('shows a slab test with %s, which the level’s own view does not', async (_name, mistake) => {
    expect(await differing(slabTest(mistake))).toBe(0);
    // The crate seen from above is 0.8 m square, about 28 × 28 pixels: a mistake on every one of its rays.
    expect(await differing(slabTest(mistake), camera)).toBeGreaterThan(500);
  });
});
