import { msg, str } from '@lit/localize';
import { wordedIssue } from '../util/issue.ts';
import { packJson, unpackJson } from '../util/packed-json.ts';
import { parseScene, type SceneParseResult } from '../scene/scene-schema.ts';
import type { Scene } from '../scene/scene.ts';
import { MAX_SCENE_FILE_BYTES } from './scene-file.ts';

/**
 * A scene as a link: `#/s/<payload>`, the payload being the scene's JSON compressed with
 * zlib deflate and written in base64url. Everything is in the fragment, so no server ever
 * sees the scene and the link works from any static host.
 *
 * zlib (not raw deflate) because it ends in a checksum: a link cut short in a chat message
 * or with one character changed fails with a message instead of opening a subtly different
 * scene. The scene format carries its own `version`, so the link needs none.
 */

export const SCENE_LINK_PREFIX = '#/s/';

/** Links longer than this are cut by some chat and mail programs: the panel suggests a file instead. */
export const LONG_LINK_CHARACTERS = 8000;

/** Whether an address fragment is meant as a scene link (damaged or not). */
export function isSceneFragment(hash: string): boolean {
  return hash.startsWith(SCENE_LINK_PREFIX);
}

/** The fragment (with its `#`) that opens `scene`. */
export async function encodeSceneLink(scene: Scene): Promise<string> {
  return `${SCENE_LINK_PREFIX}${await packJson(scene)}`;
}

/** The whole address to share: the app's address without its fragment, plus the scene's. */
export async function sceneLinkUrl(scene: Scene, appAddress: string): Promise<string> {
  return `${appAddress.replace(/#.*$/, '')}${await encodeSceneLink(scene)}`;
}

/**
 * Reads a scene fragment, checking the link (characters, checksum, size), the JSON and the
 * scene; problems are the scene schema's `path: reason` lines, or one reason for the link.
 */
export async function decodeSceneLink(hash: string): Promise<SceneParseResult> {
  if (!isSceneFragment(hash)) return damaged(msg('it does not start with #/s/'));
  const unpacked = await unpackJson(hash.slice(SCENE_LINK_PREFIX.length), MAX_SCENE_FILE_BYTES);
  if (unpacked.ok) return parseScene(unpacked.value);
  // The whole reason in the learner's language.
  switch (unpacked.problem) {
    case 'not-base64url':
      return damaged(msg('it contains characters that cannot be part of a link, or it was cut short'));
    case 'damaged':
      return damaged(msg('it was cut short or changed'));
    case 'too-large':
      return damaged(msg(str`it unpacks to more than ${unpacked.limit / 1024} kB, more than any scene`));
    case 'not-json':
      return { ok: false, errors: [unpacked.issue] };
  }
}

/** A problem with the link itself (not with a field of the scene): a reason without a path. */
function damaged(reason: string): SceneParseResult {
  return { ok: false, errors: [wordedIssue(null, reason)] };
}
