import { describe, expect, it } from 'vitest';
import { discPointBuffer } from '../../src/tracer/disc-samples.ts';
import { MAX_LIGHTS, MAX_SUB_SAMPLES, RANDOM_STREAMS, type StreamPlace } from '../../src/tracer/random-streams.ts';
import { hashKey } from '../../src/tracer/sampler.ts';
import { LIMITS } from '../../src/scene/scene-limits.ts';

/**
 * The tracer's random streams are kept apart by the numbers of random-streams.ts. Each
 * stands in a key where an index can stand too (a sub-sample's, a light's): were a stream's
 * number one of those indices, its numbers would be that sub-sample's or that light's.
 */

/** The indices that share a stream's place in the key: every one below this bound. */
const INDICES_BELOW: Record<StreamPlace, number> = { 'pixel sample': MAX_SUB_SAMPLES, hit: MAX_LIGHTS };

describe('the random streams', () => {
  it('are distinct', () => {
    const streams = RANDOM_STREAMS.map(({ stream }) => stream);
    expect(new Set(streams).size).toBe(streams.length);
  });

  it('lie above every index that shares their place in a key, bounds taken from the scene limits', () => {
    // n²·k lens/time rays per pixel sample at most, and no more than a pixel's primary rays.
    expect(MAX_SUB_SAMPLES).toBe(Math.min(LIMITS.lensSamples[1] ** 2 * LIMITS.timeSamples[1], LIMITS.primaryRaysPerPixel[1]));
    expect(MAX_LIGHTS).toBe(LIMITS.lightCount[1]);
    for (const { name, stream, place } of RANDOM_STREAMS) {
      expect(Number.isInteger(stream) && stream < 2 ** 31, name).toBe(true);
      expect(stream, `${name} stream`).toBeGreaterThanOrEqual(INDICES_BELOW[place]);
    }
  });

  it('key numbers no sub-sample or light of the same pixel sample draws', () => {
    const [seed, x, y, sample] = [7, 3, 4, 2];
    const sampleKey = hashKey(seed, x, y, sample);
    const keyAt = (place: StreamPlace, index: number) => (place === 'pixel sample' ? hashKey(seed, x, y, sample, index) : hashKey(sampleKey, index, 0));
    for (const place of ['pixel sample', 'hit'] as const) {
      const indexKeys = new Set(Array.from({ length: INDICES_BELOW[place] }, (_, index) => keyAt(place, index)));
      const streamKeys = RANDOM_STREAMS.filter((stream) => stream.place === place).map(({ stream }) => keyAt(place, stream));
      expect(indexKeys.size, place).toBe(INDICES_BELOW[place]);
      for (const key of streamKeys) expect(indexKeys.has(key), place).toBe(false);
    }
  });

  it('draw into buffers sized for the largest counts the limits allow', () => {
    const mostPerSide = Math.max(LIMITS.lensSamples[1], LIMITS.glossySamples[1]);
    expect(discPointBuffer().length).toBe(mostPerSide * mostPerSide * 2);
  });
});
