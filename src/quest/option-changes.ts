import { z } from 'zod';
import { describeValue } from '../scene/scene-issues.ts';
import { isRecord } from '../util/is-record.ts';

/**
 * Changes to lab options that have no schema of their own (the ray panel's, the BVH view's),
 * as level files write them: each field must exist in `defaults` with the same type.
 */
export function optionChanges<Options extends object>(defaults: Options) {
  return z.custom<Partial<Options>>((value) => optionProblems(defaults, value).length === 0, {
    error: (issue) => optionProblems(defaults, issue.input).join('; '),
  });
}

function optionProblems(defaults: object, value: unknown): string[] {
  if (!isRecord(value)) return [`must be an object of fields to change, got ${describeValue(value)}`];
  return Object.entries(value).flatMap(([field, given]) => {
    if (!(field in defaults)) return [`unknown field "${field}" (known: ${Object.keys(defaults).join(', ')})`];
    const expected = typeof defaults[field as keyof typeof defaults];
    return typeof given === expected ? [] : [`${field} must be a ${expected}, got ${describeValue(given)}`];
  });
}
