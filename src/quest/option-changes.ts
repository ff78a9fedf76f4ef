import { z } from 'zod';
import { reasonIssue } from '../scene/scene-issues.ts';
import { isRecord } from '../util/is-record.ts';
import { gotOf, type PlainType, type Reason } from '../util/issue.ts';

/**
 * Changes to lab options that have no schema of their own (the ray panel's, the BVH view's),
 * as level files write them: each field must exist in `defaults` with the same type. Each
 * wrong field is a problem of its own, at the changes' path.
 */
export function optionChanges<Options extends object>(defaults: Options) {
  return z.custom<Partial<Options>>().superRefine((value, context) => {
    for (const reason of optionProblems(defaults, value)) context.addIssue(reasonIssue([], value, reason));
  });
}

function optionProblems(defaults: object, value: unknown): Reason[] {
  if (!isRecord(value)) return [{ code: 'notFieldChanges', got: gotOf(value) }];
  return Object.entries(value).flatMap(([field, given]): Reason[] => {
    if (!(field in defaults)) return [{ code: 'unknownOption', field, known: Object.keys(defaults) }];
    // The options' defaults are numbers, texts and switches.
    const expected = typeof defaults[field as keyof typeof defaults] as PlainType;
    return typeof given === expected ? [] : [{ code: 'optionType', field, expected, got: gotOf(given) }];
  });
}
