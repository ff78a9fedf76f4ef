import { describe, expect, it } from 'vitest';
import { defaultScene } from '../../src/scene/scene-defaults.ts';
import { emptyRayStats } from '../../src/tracer/ray-tree.ts';
import { renderTile } from '../../src/tracer/render-tile.ts';
import { tracerSceneFrom } from '../support/test-scene.ts';

const TILE = { x: 3, y: 2, width: 20, height: 15 };
const OPTIONS = { imageWidth: 40, imageHeight: 30, seed: 5 };

describe("renderTile, one sample per pixel (the render window's sharp pass)", () => {
  for (const samplePattern of ['grid', 'jittered'] as const) {
    it(`gives exactly the scene's picture without supersampling (${samplePattern} samples)`, () => {
      const scene = (supersampling: number) => tracerSceneFrom({ ...defaultScene(), settings: { ...defaultScene().settings, supersampling, samplePattern } });
      const stats = emptyRayStats();
      const sharp = renderTile(scene(3), TILE, { ...OPTIONS, samplesPerPixel: 1 }, stats);

      expect(sharp).toEqual(renderTile(scene(1), TILE, OPTIONS));
      expect(stats.primary).toBe(TILE.width * TILE.height);
      // Without the option the scene's 3×3 samples are traced.
      const full = emptyRayStats();
      renderTile(scene(3), TILE, OPTIONS, full);
      expect(full.primary).toBe(9 * TILE.width * TILE.height);
    });
  }
});
