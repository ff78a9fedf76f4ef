import { z } from 'zod';
import { gotOf, type ListItems } from '../util/issue.ts';
import { withReason } from './scene-issues.ts';

/**
 * The building blocks the scene schema is made of. Each carries its own error message where
 * the generic ones in scene-issues.ts cannot say enough (a range issue knows only the bound
 * it broke, a tuple issue not what its items are).
 */

type Range = readonly [lowest: number, highest: number];

/** A finite number in the range (zod rejects NaN and ±Infinity by itself). */
export function numberIn([lowest, highest]: Range) {
  const error = rangeError(lowest, highest);
  return z.number().min(lowest, { error }).max(highest, { error });
}

/**
 * A whole number in the range. Not `z.int()`: its issue stops all later checks, which would
 * hide the duplicate-id and mesh problems of the same file until this one is fixed.
 */
export function wholeNumberIn([lowest, highest]: Range) {
  const error = rangeError(lowest, highest);
  return z
    .number()
    .multipleOf(1, { error: (issue) => withReason(issue, { code: 'notWhole', got: gotOf(issue.input) }) })
    .min(lowest, { error })
    .max(highest, { error });
}

function rangeError(lowest: number, highest: number) {
  return (issue: { input?: unknown }) => withReason(issue, { code: 'outOfRange', lowest, highest, got: gotOf(issue.input) });
}

/** [x, y, z], [r, g, b] and the like. */
export function triple<Item extends z.ZodType>(item: Item, items: ListItems) {
  return z.tuple([item, item, item], { error: listError(3, items) });
}

/** [width, height] and the like. */
export function pair<Item extends z.ZodType>(item: Item, items: ListItems) {
  return z.tuple([item, item], { error: listError(2, items) });
}

function listError(length: number, items: ListItems) {
  return (issue: { input?: unknown }) => withReason(issue, { code: 'notListOf', length, items, got: gotOf(issue.input) });
}

/**
 * A list of `min` to `max` items, its length checked before any item is: zod checks an
 * array's length only after parsing every item, so a file of 3,000 copies of one task took
 * seconds to be told it has too many.
 */
export function listOf<Item extends z.ZodType>(item: Item, [min, max]: readonly [number, number]) {
  return z.array(z.unknown()).min(min).max(max).pipe(z.array(item));
}
