import { isRecord } from '../util/is-record.ts';
import { readJson } from '../util/read-json.ts';
import { parseScene, type SceneParseResult } from '../scene/scene-schema.ts';
import type { Scene } from '../scene/scene.ts';
import { localize, type Locale } from '../util/localized-text.ts';

/**
 * A scene as a file a learner saves, mails and loads again: the scene format of
 * docs/scene-format.md as indented JSON, named after the scene.
 */

/** File names get the part of the scene name that is safe on every system. */
const MAX_NAME_LENGTH = 40;
/** A scene file is small (256 objects are well under 200 kB); anything far larger is not one. */
export const MAX_SCENE_FILE_BYTES = 2 * 1024 * 1024;

/** The file's text: indented JSON with a final newline, readable and diffable. */
export function sceneFileText(scene: Scene): string {
  return `${JSON.stringify(scene, null, 2)}\n`;
}

/**
 * `<scene-name>.scene.json`, e.g. `three-spheres-and-a-box.scene.json`: the name in `locale`
 * (a learner in Dutch saves `een-bal-en-een-doos.scene.json`), as lower-case ASCII letters,
 * digits and hyphens (accents dropped); `scene.scene.json` when nothing remains.
 */
export function sceneFileName(scene: Scene, locale: Locale = 'en'): string {
  const slug = (scene.name === undefined ? '' : localize(scene.name, locale))
    .normalize('NFKD')
    .replace(/[\u0300-\u036f]/g, '')
    .toLowerCase()
    .replace(/[^a-z0-9]+/g, '-')
    .slice(0, MAX_NAME_LENGTH)
    .replace(/^-+|-+$/g, '');
  return `${slug || 'scene'}.scene.json`;
}

/**
 * Reads a loaded file's text as a scene: every problem as a `path: reason` line (the scene
 * schema's), or one line when the file is too large or not JSON. A level file is accepted
 * for its scene, so a teacher can start the sandbox from a level.
 */
export function readSceneFile(text: string, bytes = text.length): SceneParseResult {
  if (bytes > MAX_SCENE_FILE_BYTES) {
    const size = Math.round(bytes / 1024);
    const most = MAX_SCENE_FILE_BYTES / 1024;
    return { ok: false, errors: [{ path: '(root)', reason: { code: 'fileTooLarge', kilobytes: size, most } }] };
  }
  const json = readJson(text);
  if (!json.ok) return { ok: false, errors: [json.issue] };
  if (!isRecord(json.value) || !('tasks' in json.value && 'scene' in json.value)) return parseScene(json.value);
  const level = parseScene(json.value.scene);
  return level.ok ? level : { ok: false, errors: level.errors.map((error) => ({ ...error, path: error.path === '(root)' ? 'scene' : `scene.${error.path}` })) };
}
