import type { z } from 'zod';
import { englishGot, englishReason, gotOf, issueLine, shortened, type Issue, type Reason, type ValueType } from '../util/issue.ts';

/**
 * Turns zod's issues into the spec's problems (spec §1): a path and a coded reason
 * (src/util/issue.ts), in English `camera.fov: must be a number, got "wide"`. Ranges carry
 * their own reason where they are declared (scene-schema-parts.ts) because an issue knows
 * only the bound it broke.
 *
 * zod keeps only a message string per issue, so the error map that words a reason also
 * leaves the reason itself on the raw issue (`withReason`): zod copies the raw issue's own
 * fields into the issue it returns (tests/scene/scene-issues.test.ts pins that).
 */

/** An issue as zod hands it to an error map, or back in its result. */
type IssueWithReason = { reason?: Reason };

/** Leaves `reason` on zod's raw issue and returns its English words as zod's message. */
export function withReason(issue: object, reason: Reason): string {
  (issue as IssueWithReason).reason = reason;
  return englishReason(reason);
}

/** A rule's own issue for a zod `addIssue`, its reason riding along as the error map leaves it. */
export function reasonIssue(path: (string | number)[], input: unknown, reason: Reason) {
  return { code: 'custom' as const, path, input, message: englishReason(reason), reason };
}

/** zod's error map: the reason of an issue, from the raw issue (which still has the input). */
export const describeIssue: z.core.$ZodErrorMap = (issue) => {
  const reason = reasonOf(issue);
  return reason && withReason(issue, reason);
};

function reasonOf(issue: z.core.$ZodRawIssue): Reason | undefined {
  const got = gotOf(issue.input);
  switch (issue.code) {
    case 'invalid_type':
      if (issue.input === undefined) return { code: 'required' };
      return issue.expected in VALUE_TYPES
        ? { code: 'wrongType', expected: issue.expected as ValueType, got }
        : { code: 'wrongTypeNamed', expected: issue.expected, got };
    case 'invalid_value':
      if (issue.input === undefined) return { code: 'required' };
      return { code: 'notAllowed', allowed: allowedValues(issue.values), got };
    case 'too_small':
      if (issue.origin === 'string') return { code: 'empty' };
      if (issue.origin === 'array') return { code: 'tooFewItems', least: Number(issue.minimum), got };
      return { code: 'tooSmall', least: Number(issue.minimum), got };
    case 'too_big':
      if (issue.origin === 'string') return { code: 'tooLong', most: Number(issue.maximum) };
      if (issue.origin === 'array') return { code: 'tooManyItems', most: Number(issue.maximum), got };
      return { code: 'tooBig', most: Number(issue.maximum), got };
    case 'invalid_union':
      // A light's `type` that names no light type: zod lists the allowed values as options,
      // and its input is the whole light.
      if (typeof issue.discriminator === 'string' && Array.isArray(issue.options)) {
        const allowed = issue.options.filter((option) => option !== undefined);
        const value = (issue.input as Record<string, unknown>)[issue.discriminator];
        return { code: 'notAllowed', allowed: allowedValues(allowed), got: gotOf(value) };
      }
      return undefined;
    case 'invalid_format':
      // An id that breaks its pattern (an event's in the log): zod's own words, with the pattern.
      return issue.format === 'regex' && issue.pattern !== undefined ? { code: 'notMatching', pattern: String(issue.pattern) } : undefined;
    case 'unrecognized_keys':
      return { code: 'unknownFields', names: issue.keys.map(shortened) };
    default:
      return undefined;
  }
}

/** The zod type names a file field of ours can have. */
const VALUE_TYPES: Record<ValueType, true> = { number: true, string: true, boolean: true, object: true, array: true };

/** One allowed value is pictured as a got value is; several are written as they are. */
function allowedValues(values: readonly unknown[]): string[] {
  return values.length === 1 ? [describeValue(values[0])] : values.map(String);
}

/**
 * The problems of a failed parse, in the order zod found them. Once a value has the wrong
 * type, further issues about it add nothing: zod checks a string's length even on a list
 * (both have a length), which would add "must have at least 1 items" to "must be a string".
 * An issue no error map gave a reason (a rule's own message) keeps its words.
 */
export function issuesOf(issues: readonly z.core.$ZodIssue[]): Issue[] {
  const wrongType = new Set<string>();
  const found: Issue[] = [];
  for (const issue of issues) {
    const path = formatPath(issue.path);
    if (wrongType.has(path)) continue;
    if (issue.code === 'invalid_type') wrongType.add(path);
    found.push({ path, reason: (issue as IssueWithReason).reason ?? { code: 'worded', text: issue.message } });
  }
  return found;
}

/** The problems of a failed parse as English `path: reason` lines. */
export function formatIssues(issues: readonly z.core.$ZodIssue[]): string[] {
  return issuesOf(issues).map(issueLine);
}

/** `objects[2].material.color[0]`; the empty path is `(root)`. */
export function formatPath(path: readonly PropertyKey[]): string {
  let text = '';
  for (const key of path) {
    if (typeof key === 'number') text += `[${key}]`;
    else text += text === '' ? shortened(String(key)) : `.${shortened(String(key))}`;
  }
  return text === '' ? '(root)' : text;
}

/** A short, JSON-like picture of a value for "got …", in English (for reasons not coded yet). */
export function describeValue(value: unknown): string {
  return englishGot(gotOf(value));
}
