import { msg, str } from '@lit/localize';
import { localNumbers } from '../../../i18n/number-format.ts';
import type { RayTests } from '../../../tracer/triangle-test-count.ts';

/**
 * The sentences of the acceleration panel's "This ray’s tests": what one pixel's ray tested,
 * said so that no two lines contradict each other.
 */

const NUMBER = localNumbers();
const PERCENT = localNumbers({ minimumFractionDigits: 1, maximumFractionDigits: 1 });

/**
 * The share of all triangles the ray did not test, in per cent, rounded DOWN to a tenth: a
 * ray that tested 4 of 8,624 triangles skipped 99.95 %, which rounded to the nearest tenth
 * would read "100.0 %" beside the 4 it tested. Rounded down it reads 99.9 %, which is true.
 */
export function skippedPercent(tests: Pick<RayTests, 'triangles' | 'bruteForce'>): number {
  if (tests.bruteForce === 0) return 0;
  return Math.floor((1000 * (tests.bruteForce - tests.triangles)) / tests.bruteForce) / 10;
}

/** "This ray tested 12 of 8,624 triangles: the BVH skipped 99.8 %." */
export function rayTestsHeadline(tests: RayTests): string {
  if (tests.bruteForce === 0) return msg('No model made of triangles in this scene: this ray tested no triangles.');
  const models = tests.objects.filter((object) => object.mesh !== null);
  if (models.every((object) => !object.boundsHit)) {
    return msg(str`This ray tested 0 of ${NUMBER.format(tests.bruteForce)} triangles: it missed the bounding box of every model.`);
  }
  return msg(
    str`This ray tested ${NUMBER.format(tests.triangles)} of ${NUMBER.format(tests.bruteForce)} triangles: the BVH skipped ${PERCENT.format(skippedPercent(tests))}\u00a0%.`,
  );
}

/**
 * "Pixel 3, 4: its ray tested 4 bounding boxes (one per object) and went through 1 of them:
 * Floor." The boxes it went through are named, so that a ray that missed every model's box
 * but went through the floor's does not seem to contradict the headline.
 * @param name an object's name as the scene list shows it
 */
export function boxesLine(pixel: readonly [number, number], tests: RayTests, name: (id: string) => string): string {
  const [column, row] = pixel;
  const entered = tests.objects.filter((object) => object.boundsHit).map((object) => name(object.id));
  if (entered.length === 0) {
    return msg(str`Pixel ${column}, ${row}: its ray tested ${tests.boundsTests} bounding boxes (one per object) and went through none of them.`);
  }
  return msg(
    str`Pixel ${column}, ${row}: its ray tested ${tests.boundsTests} bounding boxes (one per object) and went through ${entered.length} of them: ${entered.join(', ')}.`,
  );
}
