import type { SamplePattern } from '../scene/scene.ts';
import { PIXEL_POSITION_STREAM } from './random-streams.ts';
import { hashKey, RandomStream } from './sampler.ts';

const stream = new RandomStream();

/**
 * Where sample `index` of an s×s set lies inside pixel (x, y), as offsets in [0, 1).
 * grid: cell centres ((i+0.5)/s, (j+0.5)/s) (spec §2, the default);
 * jittered: a uniform point inside each cell (stratified sampling);
 * random: s² uniform points anywhere in the pixel (to show why stratifying helps).
 */
export function samplePosition(pattern: SamplePattern, s: number, index: number, x: number, y: number, seed: number, out: [number, number]): [number, number] {
  const i = index % s;
  const j = Math.floor(index / s);
  if (pattern === 'grid') {
    out[0] = (i + 0.5) / s;
    out[1] = (j + 0.5) / s;
    return out;
  }
  stream.reset(hashKey(seed, x, y, index, PIXEL_POSITION_STREAM));
  const u = stream.next();
  const v = stream.next();
  if (pattern === 'jittered') {
    out[0] = (i + u) / s;
    out[1] = (j + v) / s;
  } else {
    out[0] = u;
    out[1] = v;
  }
  return out;
}
