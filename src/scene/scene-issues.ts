import type { z } from 'zod';

/**
 * Turns zod's issues into the spec's `path: reason` lines (spec §1), e.g.
 * `camera.fov: must be a number, got "wide"`. Ranges carry their own message where they are
 * declared (scene-schema-parts.ts) because an issue knows only the bound it broke.
 */

/** zod's error map: the reason part of a line, from the raw issue (which still has the input). */
export const describeIssue: z.core.$ZodErrorMap = (issue) => {
  const got = `got ${describeValue(issue.input)}`;
  switch (issue.code) {
    case 'invalid_type':
      if (issue.input === undefined) return 'is required';
      return `must be ${EXPECTED[issue.expected] ?? issue.expected}, ${got}`;
    case 'invalid_value':
      if (issue.input === undefined) return 'is required';
      return `must be ${oneOf(issue.values)}, ${got}`;
    case 'too_small':
      if (issue.origin === 'string') return 'must not be empty';
      if (issue.origin === 'array') return `must have at least ${issue.minimum} items, ${got}`;
      return `must be at least ${issue.minimum}, ${got}`;
    case 'too_big':
      if (issue.origin === 'string') return `must be at most ${issue.maximum} characters long`;
      if (issue.origin === 'array') return `must have at most ${issue.maximum} items, ${got}`;
      return `must be at most ${issue.maximum}, ${got}`;
    case 'invalid_union':
      // A light's `type` that names no light type: zod lists the allowed values as options,
      // and its input is the whole light.
      if (typeof issue.discriminator === 'string' && Array.isArray(issue.options)) {
        const allowed = issue.options.filter((option) => option !== undefined);
        const value = (issue.input as Record<string, unknown>)[issue.discriminator];
        return `must be ${oneOf(allowed)}, got ${describeValue(value)}`;
      }
      return undefined;
    case 'unrecognized_keys':
      return `unknown field${issue.keys.length > 1 ? 's' : ''} ${issue.keys.map((key) => JSON.stringify(shortened(key))).join(', ')}`;
    default:
      return undefined;
  }
};

/** What each zod type name means to someone editing a scene file. */
const EXPECTED: Partial<Record<string, string>> = {
  number: 'a number',
  string: 'a string',
  boolean: 'true or false',
  object: 'an object',
  array: 'a list',
};

/**
 * `path: reason` for every issue, in the order zod found them. Once a value has the wrong
 * type, further issues about it add nothing: zod checks a string's length even on a list
 * (both have a length), which would add "must have at least 1 items" to "must be a string".
 */
export function formatIssues(issues: readonly z.core.$ZodIssue[]): string[] {
  const wrongType = new Set<string>();
  const lines: string[] = [];
  for (const issue of issues) {
    const path = formatPath(issue.path);
    if (wrongType.has(path)) continue;
    if (issue.code === 'invalid_type') wrongType.add(path);
    lines.push(`${path}: ${issue.message}`);
  }
  return lines;
}

/** `objects[2].material.color[0]`; the empty path is `(root)`. */
function formatPath(path: readonly PropertyKey[]): string {
  let text = '';
  for (const key of path) {
    if (typeof key === 'number') text += `[${key}]`;
    else text += text === '' ? shortened(String(key)) : `.${shortened(String(key))}`;
  }
  return text === '' ? '(root)' : text;
}

/** Text quoted in a message: at most 40 characters, so that a 2 MB key or value is not echoed back. */
function shortened(text: string): string {
  return text.length > 40 ? `${text.slice(0, 40)}…` : text;
}

/** A short, JSON-like picture of a value for "got …" (never the whole of a big object). */
export function describeValue(value: unknown): string {
  if (value === undefined) return 'nothing';
  if (typeof value === 'string') return JSON.stringify(shortened(value));
  if (Array.isArray(value)) return value.length === 1 ? 'a list of 1 item' : `a list of ${value.length} items`;
  if (value !== null && typeof value === 'object') return 'an object';
  return String(value);
}

function oneOf(values: readonly unknown[]): string {
  if (values.length === 1) return describeValue(values[0]);
  return `one of ${values.join(', ')}`;
}
