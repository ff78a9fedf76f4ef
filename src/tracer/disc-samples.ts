import { concentricDisc } from './lights.ts';
import type { RandomStream } from './sampler.ts';
import { LIMITS } from '../scene/scene-limits.ts';

/**
 * "Jittered disc points" (distribution-effects §2): one uniform point in each of the q×q
 * equal cells of the unit square, mapped onto the unit disc by Shirley and Chiu's
 * concentric map, which keeps the cells equal in area (so the points stay stratified),
 * as the disc area light does. Writes q² (x, y) pairs into `out` and returns it.
 */
export function jitteredDiscPoints(q: number, random: RandomStream, out: Float64Array): Float64Array {
  for (let cell = 0; cell < q * q; cell++) {
    const u = (((cell % q) + random.next()) / q) * 2 - 1;
    const v = ((Math.floor(cell / q) + random.next()) / q) * 2 - 1;
    const [x, y] = concentricDisc(u, v);
    out[cell * 2] = x;
    out[cell * 2 + 1] = y;
  }
  return out;
}

/** The largest q the scene's limits allow, for lens points and for glossy rays. */
const MOST_PER_SIDE = Math.max(LIMITS.lensSamples[1], LIMITS.glossySamples[1]);

/** Room for the q² (x, y) points of the largest q. */
export function discPointBuffer(): Float64Array {
  return new Float64Array(MOST_PER_SIDE * MOST_PER_SIDE * 2);
}
