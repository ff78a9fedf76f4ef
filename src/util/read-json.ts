import { describeJsonError } from './json-error.ts';

export type JsonRead = { ok: true; value: unknown } | { ok: false; error: string };

/** The value in a JSON text (level, index or progress file), or the one-line `(root): …` reason it is not JSON. */
export function readJson(text: string): JsonRead {
  // Windows editors may start a UTF-8 file with a byte-order mark, which JSON.parse refuses.
  const json = text.replace(/^\uFEFF/, '');
  try {
    return { ok: true, value: JSON.parse(json) };
  } catch {
    return { ok: false, error: describeJsonError(json) };
  }
}
