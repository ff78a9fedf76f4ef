import type { Issue } from './issue.ts';
import { jsonIssue } from './json-error.ts';

export type JsonRead = { ok: true; value: unknown } | { ok: false; issue: Issue };

/** The value in a JSON text (level, index or progress file), or the `(root)` issue saying why it is not JSON. */
export function readJson(text: string): JsonRead {
  // Windows editors may start a UTF-8 file with a byte-order mark, which JSON.parse refuses.
  const json = text.replace(/^\uFEFF/, '');
  try {
    return { ok: true, value: JSON.parse(json) };
  } catch {
    return { ok: false, issue: jsonIssue(json) };
  }
}
