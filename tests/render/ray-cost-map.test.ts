import { describe, expect, it } from 'vitest';
import { RayCostMap } from '../../src/render/ray-cost-map.ts';

describe("the map of where an image's rays go", () => {
  it("assumes the estimate's rays per sample before any tile, then the mean of the tiles traced where it knows nothing", () => {
    const map = new RayCostMap(64, 64, 7);
    expect(map.snapshot().predictImage(1)).toBeCloseTo(7 * 64 * 64);
    // The top half traced at one sample per 4×4 block: 128 samples, 10 rays each.
    map.record({ x: 0, y: 0, width: 64, height: 32 }, 128, 1280);
    const snapshot = map.snapshot();
    expect(snapshot.predict({ x: 0, y: 0, width: 64, height: 32 }, 1)).toBeCloseTo(10 * 64 * 32);
    expect(snapshot.predict({ x: 0, y: 32, width: 64, height: 32 }, 1)).toBeCloseTo(10 * 64 * 32);
  });

  it("keeps each cell's own cost: a dear corner stays dear", () => {
    const map = new RayCostMap(64, 64, 1);
    map.record({ x: 0, y: 0, width: 32, height: 32 }, 1024, 102_400); // 100 rays a sample
    for (const [x, y] of [
      [32, 0],
      [0, 32],
      [32, 32],
    ])
      map.record({ x, y, width: 32, height: 32 }, 1024, 2048); // 2
    const snapshot = map.snapshot();
    // At 4 samples per pixel (2×2 supersampling).
    expect(snapshot.predict({ x: 0, y: 0, width: 16, height: 16 }, 4)).toBeCloseTo(100 * 256 * 4);
    expect(snapshot.predict({ x: 48, y: 48, width: 16, height: 16 }, 4)).toBeCloseTo(2 * 256 * 4);
  });

  it('predicts tiles that add up to the whole image, whatever their size and the cells they cut', () => {
    const [width, height] = [301, 203];
    const map = new RayCostMap(width, height, 3);
    for (let y = 0; y < height; y += 13) {
      for (let x = 0; x < width; x += 11) {
        const tile = { x, y, width: Math.min(11, width - x), height: Math.min(13, height - y) };
        map.record(tile, tile.width * tile.height, (1 + ((x * 7 + y * 3) % 50)) * tile.width * tile.height);
      }
    }
    const snapshot = map.snapshot();
    let sum = 0;
    for (let y = 0; y < height; y += 7) {
      for (let x = 0; x < width; x += 5) sum += snapshot.predict({ x, y, width: Math.min(5, width - x), height: Math.min(7, height - y) }, 1 / 16);
    }
    expect(sum / snapshot.predictImage(1 / 16)).toBeCloseTo(1, 9);
  });

  it('a snapshot does not move when more tiles are recorded', () => {
    const map = new RayCostMap(32, 32, 5);
    const snapshot = map.snapshot();
    map.record({ x: 0, y: 0, width: 32, height: 32 }, 64, 6400);
    expect(snapshot.predictImage(1)).toBeCloseTo(5 * 32 * 32);
    expect(map.snapshot().predictImage(1)).toBeCloseTo(100 * 32 * 32);
  });
});
