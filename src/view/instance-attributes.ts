/**
 * What each drawn ray looks like besides where it is: its colour, alpha, growth, dash pattern,
 * arrowhead place and stop plate, written into the instance buffers (instance-buffers.ts) from a
 * SegmentList. A pixel's sample paths take their own dashes (path-dashes.ts), a moment its stripe.
 */
import { arrowAt } from './ray-shader.ts';
import type { InstanceBuffers } from './instance-buffers.ts';
import type { SegmentList } from './ray-visibility.ts';
import { FILLED_GAP_KEYS, RAY_COLOR_KEYS, RAY_DASHES, type RayColorKey, STOPPED_KEYS } from './ray-palette.ts';
import { PATH_DASHES } from './path-dashes.ts';
import { timeStripe } from './time-colors.ts';

/**
 * RAY_DASHES as (dash, gap) pairs by colour-key index, the form SegmentList.colorKey holds: a
 * rebuild copies two numbers per ray from it. Looking each pattern up by its name and copying
 * it with TypedArray.set was a third of a 10k-ray rebuild.
 */
export const DASHES_BY_KEY = dashesByKey(RAY_DASHES);

/** PATH_DASHES in the same form: a pixel's sample paths (path-dashes.ts). */
export const PATH_DASHES_BY_KEY = dashesByKey(PATH_DASHES);

/** Patterns by key as (dash, gap) pairs by colour-key index; a filled gap is stored negative (ray-shader.ts aDash). */
function dashesByKey(dashes: Readonly<Record<RayColorKey, readonly [number, number]>>): Float32Array {
  return Float32Array.from(RAY_COLOR_KEYS.flatMap((key) => (FILLED_GAP_KEYS.has(key) ? [dashes[key][0], -dashes[key][1]] : dashes[key])));
}

/** Where each key's arrowhead sits (ray-shader.ts arrowAt), by colour-key index like DASHES_BY_KEY. */
const ARROW_AT_BY_KEY = Float32Array.from(RAY_COLOR_KEYS.map(arrowAt));

/** 1 for the keys with a stop plate at their end (STOPPED_KEYS), by colour-key index. */
const STOP_BY_KEY = Float32Array.from(RAY_COLOR_KEYS.map((key) => (STOPPED_KEYS.has(key) ? 1 : 0)));

/** Whether any of the drawn rays ends stopped (a blocked shadow ray): only then are stop plates drawn. */
export function anyStopped(list: SegmentList): boolean {
  for (let i = 0; i < list.count; i++) if (STOP_BY_KEY[list.colorKey[i]] === 1) return true;
  return false;
}

/** Writes the first list.count instances' looks, the alpha scaled by `opacity`, and uploads them. */
export function writeInstanceAttributes(buffers: InstanceBuffers, list: SegmentList, opacity: number, dashes: Float32Array): void {
  const { count } = list;
  (buffers.color.array as Float32Array).set(list.color.subarray(0, count * 3));
  const alpha = buffers.alpha.array as Float32Array;
  const growth = buffers.growth.array as Float32Array;
  const dash = buffers.dash?.array as Float32Array | undefined;
  const arrowAt = buffers.arrowAt?.array as Float32Array | undefined;
  const stop = buffers.stop?.array as Float32Array | undefined;
  for (let i = 0; i < count; i++) {
    alpha[i] = list.alpha[i] * opacity;
    growth[i * 2] = list.start[i];
    growth[i * 2 + 1] = list.length[i];
    if (dash && arrowAt && stop) {
      const key = list.colorKey[i];
      if (list.moment[i] >= 0) timeStripe(list.moment[i], dash, i * 2);
      else {
        dash[i * 2] = dashes[key * 2];
        dash[i * 2 + 1] = dashes[key * 2 + 1];
      }
      arrowAt[i] = ARROW_AT_BY_KEY[key];
      stop[i] = STOP_BY_KEY[key];
    }
  }
  buffers.commit(count);
}
