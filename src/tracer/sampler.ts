/**
 * Deterministic random numbers keyed by (pixel, sample, light), as pbrt-v4's
 * IndependentSampler::StartPixelSample does: re-tracing one pixel for its ray tree draws
 * exactly the numbers the full render drew there, so the tree's colour equals the image's.
 * No state is shared between pixels, so tiles can be rendered in any order on any worker.
 */

/** A 32-bit integer hash (Chris Wellons' "lowbias32", https://nullprogram.com/blog/2018/07/31/). */
function mix32(x: number): number {
  x ^= x >>> 16;
  x = Math.imul(x, 0x7feb352d);
  x ^= x >>> 15;
  x = Math.imul(x, 0x846ca68b);
  x ^= x >>> 16;
  return x >>> 0;
}

/** The key before any integer is hashed in. */
const KEY_START = 0x9e3779b9;

/**
 * One more integer hashed into a key: hashKey(a, b, c) is hashIn(hashKey(a, b), c) to the
 * bit, so a caller that draws many keys with the same first integers hashes those once.
 */
export function hashIn(key: number, value: number): number {
  return mix32(key ^ mix32(value | 0));
}

/**
 * Hashes up to five integers, in order, into one 32-bit key. Fixed parameters, not a rest
 * array: the tracer calls this several times per sample, and the array a rest parameter
 * makes for each call was garbage the collector had to clear (about 2 % of a render).
 */
export function hashKey(a: number, b?: number, c?: number, d?: number, e?: number): number {
  let key = hashIn(KEY_START, a);
  if (b === undefined) return key;
  key = hashIn(key, b);
  if (c === undefined) return key;
  key = hashIn(key, c);
  if (d === undefined) return key;
  key = hashIn(key, d);
  return e === undefined ? key : hashIn(key, e);
}

/** 2^-32: multiplying by it is dividing by 2^32, to the bit, without a division. */
const TWO_TO_MINUS_32 = 1 / 4294967296;

/** A small stream of uniform numbers in [0, 1) from one key (a counter-based generator). */
export class RandomStream {
  // Kept as a signed 32-bit integer: the hash reads its input modulo 2^32 whatever its sign
  // (docs/performance.md, "Integer hashing").
  private key = 0;
  private counter = 0;

  /** Restarts the stream for a new key, e.g. hashKey(seed, x, y, sample, light). */
  reset(key: number): this {
    this.key = key | 0;
    this.counter = 0;
    return this;
  }

  /**
   * One hash per draw of key + counter·φ (a Weyl sequence, as SplitMix does; Steele et al.,
   * "Fast splittable pseudorandom number generators", 2014): the golden-ratio step keeps
   * consecutive inputs far apart, so the hash's output is well mixed.
   */
  next(): number {
    return mix32((this.key + Math.imul(this.counter++, 0x9e3779b9)) | 0) * TWO_TO_MINUS_32;
  }
}
