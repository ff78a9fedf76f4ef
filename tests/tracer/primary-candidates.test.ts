import { Vector3 } from 'three';
import { describe, expect, it } from 'vitest';
import { objectGridScene } from '../../bench/object-grid-scene.ts';
import { Hit } from '../../src/tracer/hit.ts';
import { PrimaryCandidates } from '../../src/tracer/primary-candidates.ts';
import { rayMeetsBox } from '../../src/tracer/ray-box.ts';
import { Ray } from '../../src/tracer/ray.ts';
import { renderTile } from '../../src/tracer/render-tile.ts';
import { hashKey, RandomStream } from '../../src/tracer/sampler.ts';
import { tracePixel } from '../../src/tracer/trace-pixel.ts';
import { buildTracerScene, type TracerScene } from '../../src/tracer/tracer-scene.ts';
import { matte, pointLight, tracerSceneFrom } from '../support/test-scene.ts';

const random = new RandomStream().reset(hashKey(31));

/**
 * Spheres, boxes and cylinders, each one twice in the same place (every hit on it is an
 * exact tie, which the first object tested wins), seen from straight above: some tiles lie
 * across the sign changes of the rays' directions.
 */
function lookingDown(): TracerScene {
  const kinds = ['sphere', 'box', 'cylinder'];
  const objects = Array.from({ length: 15 }, (_, i) => ({
    shape: kinds[i % 3],
    position: [(i % 5) - 2, (i % 4) * 0.3, Math.floor(i / 5) - 1],
    rotation: [0, i * 20, 0],
    scale: [0.8, 0.8, 0.8],
  }));
  return tracerSceneFrom({
    camera: { position: [0, 6, 0], target: [0, 0, 0], fov: 60 },
    // The two differ in colour only, so that an image shows which one won a tie.
    objects: objects.flatMap((object, i) => [
      { ...object, id: `a${i}`, material: matte([1, 0.2, 0.2]) },
      { ...object, id: `b${i}`, material: matte([0.2, 0.2, 1]) },
    ]),
    lights: [pointLight([0, 8, 0])],
  });
}

function grid(side: number, size: number): TracerScene {
  const scene = objectGridScene(side);
  return buildTracerScene({ ...scene, settings: { ...scene.settings, imageSize: [size, size] } }, new Map());
}

/**
 * Every primary ray of every tile (at random points of its pixels) finds, from the tile's
 * list, the object and distance the BVH walk finds, to the bit; the counts show that the
 * lists were used and are shorter than the scene.
 */
function compareTiles(scene: TracerScene, size: number, tileSide: number, block = 1) {
  const candidates = new PrimaryCandidates();
  const width = size / block;
  const direction = new Vector3();
  const ray = new Ray();
  const [fromList, fromWalk] = [new Hit(), new Hit()];
  let listed = 0;
  let walked = 0;
  let hits = 0;
  let longest = 0;
  for (let y = 0; y < size; y += tileSide) {
    for (let x = 0; x < size; x += tileSide) {
      candidates.set(scene, x / block, y / block, (x + tileSide) / block, (y + tileSide) / block, width, width);
      longest = Math.max(longest, candidates.count);
      for (let k = 0; k < 24; k++) {
        // A preview's rays start at its blocks' corners, scaled down; a full pass's anywhere in its pixels.
        const px = (x + Math.floor(random.next() * tileSide)) / block + random.next();
        const py = (y + Math.floor(random.next() * tileSide)) / block + random.next();
        ray.set(scene.camera.eye, scene.camera.direction(px, py, width, width, direction));
        scene.objects.nearest(ray, fromWalk.reset(Infinity), null);
        if (!candidates.covers(ray)) {
          walked++;
          continue;
        }
        listed++;
        fromList.reset(Infinity);
        for (let i = 0; i < candidates.count; i++) if (rayMeetsBox(ray, candidates.boxes, i * 6, fromList.t)) candidates.list[i].intersect(ray, fromList);
        expect(fromList.shape?.id).toBe(fromWalk.shape?.id);
        expect(Object.is(fromList.t, fromWalk.t)).toBe(true);
        if (fromWalk.shape) hits++;
      }
    }
  }
  return { listed, walked, hits, longest };
}

describe('the objects a tile of primary rays can hit (frustum culling)', () => {
  it("give the BVH walk's hit for every ray of the 256-object grid, from lists much shorter than the scene", () => {
    const { listed, walked, hits, longest } = compareTiles(grid(16, 128), 128, 8);
    expect(listed).toBeGreaterThan(walked);
    expect(hits).toBeGreaterThan(listed / 4);
    expect(longest).toBeGreaterThan(0);
    expect(longest).toBeLessThan(64);
  });

  it("give the walk's hit in a preview (tiles traced block times smaller)", () => {
    const { listed, hits } = compareTiles(grid(16, 128), 128, 16, 4);
    expect(listed).toBeGreaterThan(0);
    expect(hits).toBeGreaterThan(0);
  });

  it("give the walk's hit between objects in the same place (ties), with rays of other signs left to the walk", () => {
    const { listed, walked, hits } = compareTiles(lookingDown(), 56, 8);
    expect(listed).toBeGreaterThan(0);
    expect(walked).toBeGreaterThan(0);
    expect(hits).toBeGreaterThan(0);
  });

  it('lists nothing for a camera with a lens (its rays start all over the lens)', () => {
    const scene = grid(3, 64);
    const lens = buildTracerScene({ ...scene.source, camera: { ...scene.source.camera, aperture: 0.2 } }, new Map());
    expect(new PrimaryCandidates().set(lens, 0, 0, 16, 16, 64, 64).count).toBe(-1);
    expect(new PrimaryCandidates().set(scene, 0, 0, 16, 16, 64, 64).count).toBeGreaterThanOrEqual(0);
  });

  it("leave a rendered image equal to its pixels' ray trees, which walk the BVH", () => {
    for (const scene of [grid(16, 8), lookingDown()]) {
      const [width, height] = scene.source.camera.pixels;
      for (let y = 0; y < height; y += 2) {
        for (let x = 0; x < width; x += 2) {
          const tile = renderTile(scene, { x, y, width: 2, height: 2 }, { imageWidth: width, imageHeight: height, seed: 3 });
          for (let i = 0; i < 4; i++) {
            const { color } = tracePixel(scene, x + (i % 2), y + (i >> 1), 3);
            expect(color).toEqual([tile[i * 3], tile[i * 3 + 1], tile[i * 3 + 2]]);
          }
        }
      }
    }
  });
});
