import { describe, expect, it } from 'vitest';
import { RandomStream } from '../../src/tracer/sampler.ts';

/**
 * The stream must draw exactly the numbers of its definition in unsigned 32-bit arithmetic
 * (the native anchor's `mix32(key + counter·0x9e3779b9) / 2^32`), whatever the key's top
 * bit: the image, and the anchor's agreement with it, depend on every jittered sample.
 */
const MASK = 0xffffffffn;

function mix32(x: bigint): bigint {
  x ^= x >> 16n;
  x = (x * 0x7feb352dn) & MASK;
  x ^= x >> 15n;
  x = (x * 0x846ca68bn) & MASK;
  x ^= x >> 16n;
  return x;
}

function definition(key: number, count: number): number[] {
  return Array.from({ length: count }, (_, counter) => Number(mix32((BigInt(key) + BigInt(counter) * 0x9e3779b9n) & MASK)) / 2 ** 32);
}

describe('the random stream', () => {
  it('draws the numbers of its unsigned 32-bit definition, for keys on both sides of 2^31', () => {
    for (const key of [0, 1, 12345, 0x7fffffff, 0x80000000, 0x9e3779b9, 0xfffffffe, 0xffffffff]) {
      const stream = new RandomStream().reset(key);
      expect(Array.from({ length: 64 }, () => stream.next())).toEqual(definition(key, 64));
    }
  });

  it('stays in [0, 1)', () => {
    const stream = new RandomStream().reset(0xdeadbeef);
    for (let i = 0; i < 10_000; i++) {
      const value = stream.next();
      expect(value).toBeGreaterThanOrEqual(0);
      expect(value).toBeLessThan(1);
    }
  });
});
