import type { Vec3 } from '../../src/quest/code-labs/code-lab-grading.ts';

export type HitBox = (origin: Vec3, direction: Vec3, boxMin: Vec3, boxMax: Vec3) => number | null;

/** The ways learners get the slab test wrong, each one named for its misconception. */
export interface SlabMistakes {
  parallelMisses?: boolean;
  parallelIgnored?: boolean;
  nanThrough?: boolean;
  acceptNegative?: boolean;
  noInside?: boolean;
  noSwap?: boolean;
  touchMisses?: boolean;
}

const AXES = ['x', 'y', 'z'] as const;

/** The textbook slab test (Shirley & Marschner §12.3.1) with Math.min/max, written as a learner would, with the mistakes asked for. */
export function slabTest(wrong: SlabMistakes = {}): HitBox {
  return (origin, direction, boxMin, boxMax) => {
    let near = -Infinity;
    let far = Infinity;
    for (const axis of AXES) {
      if (direction[axis] === 0 && wrong.parallelMisses) return null;
      if (direction[axis] === 0 && wrong.parallelIgnored) continue;
      const t0 = (boxMin[axis] - origin[axis]) / direction[axis];
      const t1 = (boxMax[axis] - origin[axis]) / direction[axis];
      near = Math.max(near, wrong.noSwap ? t0 : Math.min(t0, t1));
      far = Math.min(far, wrong.noSwap ? t1 : Math.max(t0, t1));
    }
    // The NaN-blind version: NaN > x and NaN < 0 are both false, so NaN slips through to the answer.
    if (wrong.acceptNegative) return near <= far ? near : null;
    if (wrong.nanThrough ? near > far || far < 0 : wrong.touchMisses ? !(near < far) || far <= 0 : !(near <= far) || far <= 0) return null;
    if (wrong.noInside) return near > 0 ? near : null;
    return near > 0 ? near : far;
  };
}
