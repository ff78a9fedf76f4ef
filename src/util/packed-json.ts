import type { Issue } from './issue.ts';
import { fromBase64Url, toBase64Url } from './base64url.ts';
import { readJson } from './read-json.ts';
import { deflate, inflate, InflatedTooLarge } from './zlib-bytes.ts';

/**
 * A value as link text: its JSON compressed with zlib deflate and written in base64url, as
 * the scene and assignment links carry it in the address fragment. zlib (not raw deflate)
 * because it ends in a checksum: a link cut short or with one character changed fails to
 * unpack instead of opening as something subtly different.
 */
export async function packJson(value: unknown): Promise<string> {
  return toBase64Url(await deflate(new TextEncoder().encode(JSON.stringify(value))));
}

/** Why a payload did not unpack; the caller words it for the learner (it knows what the link was for). */
export type PackedJsonProblem =
  { problem: 'not-base64url' } | { problem: 'damaged' } | { problem: 'too-large'; limit: number } | { problem: 'not-json'; issue: Issue };

export type UnpackedJson = { ok: true; value: unknown } | ({ ok: false } & PackedJsonProblem);

/**
 * The value `packJson` packed, checked all the way: the characters, the checksum, at most
 * `limit` unpacked bytes (a few hundred kilobytes of link can unpack to hundreds of
 * megabytes), UTF-8 and JSON.
 */
export async function unpackJson(payload: string, limit: number): Promise<UnpackedJson> {
  const bytes = fromBase64Url(payload);
  if (bytes === null || bytes.length === 0) return { ok: false, problem: 'not-base64url' };
  let text: string;
  try {
    text = new TextDecoder('utf-8', { fatal: true }).decode(await inflate(bytes, limit));
  } catch (error) {
    return error instanceof InflatedTooLarge ? { ok: false, problem: 'too-large', limit: error.limit } : { ok: false, problem: 'damaged' };
  }
  const json = readJson(text);
  return json.ok ? { ok: true, value: json.value } : { ok: false, problem: 'not-json', issue: json.issue };
}
