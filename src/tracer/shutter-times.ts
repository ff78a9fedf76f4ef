import type { TimePattern } from '../scene/scene.ts';
import { SHUTTER_TIME_STREAM } from './random-streams.ts';
import { hashKey, RandomStream } from './sampler.ts';

const stream = new RandomStream();

/**
 * The k shutter times τ in [0, 1) of sample `sample` of pixel (x, y), written to out[0 … k−1]
 * (distribution-effects §2). Cook, Porter and Carpenter ("Distributed Ray Tracing", 1984)
 * spread a pixel's rays over the open shutter as they spread them over the pixel, and the
 * same three patterns as samplePosition's show why jittering pays:
 * - grid: the middles (i + ½)/k, the same moments for every pixel and sample. A moving
 *   object is seen at k fixed places: k separate faint copies (aliasing in time);
 * - jittered (the default): one uniform moment in each of the k equal intervals,
 *   (i + ξ)/k, different for every pixel sample: the copies become an even streak with grain;
 * - random: k uniform moments anywhere in [0, 1): they can clump and leave gaps, so the
 *   streak is grainier than jittered at the same k.
 * One time (k = 1) is τ = 0 for every pattern: the shutter sees the scene as it stands.
 */
export function shutterTimes(pattern: TimePattern, k: number, seed: number, x: number, y: number, sample: number, out: Float64Array | number[]): void {
  if (k === 1) {
    out[0] = 0;
    return;
  }
  if (pattern === 'grid') {
    for (let i = 0; i < k; i++) out[i] = (i + 0.5) / k;
    return;
  }
  stream.reset(hashKey(seed, x, y, sample, SHUTTER_TIME_STREAM));
  if (pattern === 'jittered') for (let i = 0; i < k; i++) out[i] = (i + stream.next()) / k;
  else for (let i = 0; i < k; i++) out[i] = stream.next();
}
