import { z } from 'zod';
import { reasonIssue } from '../scene/scene-issues.ts';
import { isRecord } from '../util/is-record.ts';
import type { Reason } from '../util/issue.ts';

/**
 * How goals compare a value of the state (or of an action) with the value a level expects.
 * `{ "state": …, "op": ">=", "value": 2 }` names one comparison; the `where` and `with`
 * fields of an event goal give a condition per path: a plain value to equal, or an object
 * of comparisons that must all hold, like `{ ">=": 2, "<=": 4 }`.
 */

export const COMPARISONS = ['==', '!=', '>', '>=', '<', '<=', 'includes'] as const;
export type Comparison = (typeof COMPARISONS)[number];

/** Any value JSON can hold. */
export type JsonValue = z.core.util.JSONType;

/** Colours and positions go through sliders and conversions: equal means this close. */
const NUMBER_TOLERANCE = 1e-6;

/**
 * `==` and `!=` compare lists and objects by their contents; `>`, `>=`, `<`, `<=` need two
 * numbers; `includes` asks whether a list has the item (or a text the piece of text). A
 * value that is not there (`undefined`) equals nothing.
 */
export function compare(actual: unknown, op: Comparison, expected: JsonValue): boolean {
  switch (op) {
    case '==':
      return sameValue(actual, expected);
    case '!=':
      return !sameValue(actual, expected);
    case 'includes':
      if (Array.isArray(actual)) return actual.some((item) => sameValue(item, expected));
      return typeof actual === 'string' && typeof expected === 'string' && actual.includes(expected);
    default:
      if (typeof actual !== 'number' || typeof expected !== 'number') return false;
      if (op === '>') return actual > expected;
      if (op === '>=') return actual >= expected;
      if (op === '<') return actual < expected;
      return actual <= expected;
  }
}

function sameValue(actual: unknown, expected: JsonValue): boolean {
  if (typeof actual === 'number' && typeof expected === 'number') return Math.abs(actual - expected) <= NUMBER_TOLERANCE;
  if (Array.isArray(expected)) {
    return Array.isArray(actual) && actual.length === expected.length && expected.every((item, index) => sameValue(actual[index], item));
  }
  if (isJsonObject(expected)) {
    const keys = Object.keys(expected);
    return isRecord(actual) && Object.keys(actual).length === keys.length && keys.every((key) => sameValue(actual[key], expected[key]));
  }
  return actual === expected;
}

/** A `where`/`with` condition holds for `actual`. */
export function conditionHolds(actual: unknown, condition: JsonValue): boolean {
  const comparisons = comparisonsOf(condition);
  if (!comparisons) return compare(actual, '==', condition);
  return comparisons.every(([op, value]) => compare(actual, op, value));
}

/** The comparisons of a condition like `{ ">=": 2 }`, or undefined for a plain value. */
function comparisonsOf(condition: JsonValue): [Comparison, JsonValue][] | undefined {
  if (!isJsonObject(condition)) return undefined;
  const entries = Object.entries(condition);
  if (entries.length === 0 || !entries.every(([key]) => isComparison(key))) return undefined;
  return entries as [Comparison, JsonValue][];
}

function isComparison(key: string): key is Comparison {
  return (COMPARISONS as readonly string[]).includes(key);
}

/** Why `value` cannot be compared by `op` (ordering needs a number), or undefined. */
export function problemWithComparison(op: Comparison, value: JsonValue): Reason | undefined {
  if (['>', '>=', '<', '<='].includes(op) && typeof value !== 'number') return { code: 'comparesNumbers', op, got: JSON.stringify(value) };
  return undefined;
}

/** A condition as a level file writes it, with the mistakes a plain JSON check would let through. */
export const conditionSchema = z.json().superRefine((condition, context) => {
  if (!isJsonObject(condition)) return;
  const keys = Object.keys(condition);
  const ops = keys.filter(isComparison);
  if (ops.length > 0 && ops.length < keys.length) {
    context.addIssue(reasonIssue([], condition, { code: 'mixedCondition', ops, fields: keys.filter((key) => !isComparison(key)) }));
  }
  for (const op of ops) {
    const problem = problemWithComparison(op, condition[op]);
    if (problem) context.addIssue(reasonIssue([op], condition[op], problem));
  }
});

function isJsonObject(value: JsonValue): value is { [key: string]: JsonValue } {
  return isRecord(value);
}
