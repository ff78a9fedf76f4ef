import { describe, expect, it } from 'vitest';
import { readFileSync } from 'node:fs';
import { readSceneFile, sceneFileName, sceneFileText, MAX_SCENE_FILE_BYTES } from '../../src/app/scene-file.ts';
import { defaultScene } from '../../src/scene/scene-defaults.ts';
import type { SceneParseResult } from '../../src/scene/scene-schema.ts';
import { issueLine } from '../../src/util/issue.ts';

/** A refused file's problems as the English lines `rt validate` prints; none for a scene. */
const linesOf = (read: SceneParseResult) => (read.ok ? [] : read.errors.map(issueLine));

describe('scene files', () => {
  it('round-trips a scene through its file text', () => {
    const scene = defaultScene();
    const text = sceneFileText(scene);
    expect(text).toContain('\n  "name": {\n    "en": "Three spheres and a box",\n    "nl": "Drie bollen en een doos"\n  },\n');
    expect(text.endsWith('}\n')).toBe(true);
    expect(readSceneFile(text)).toEqual({ ok: true, scene });
  });

  it('names the file after the scene, safely', () => {
    expect(sceneFileName(defaultScene())).toBe('three-spheres-and-a-box.scene.json');
    expect(sceneFileName({ ...defaultScene(), name: 'Café / Ünïcode: ☀ test' })).toBe('cafe-unicode-test.scene.json');
    expect(sceneFileName({ ...defaultScene(), name: '☀☀' })).toBe('scene.scene.json');
    expect(sceneFileName({ ...defaultScene(), name: undefined })).toBe('scene.scene.json');
  });

  it('names the file in the learner’s language when the scene has a name per language', () => {
    const scene = { ...defaultScene(), name: { en: 'A ball and a box', nl: 'Eén bal en een doos' } };
    expect(sceneFileName(scene, 'nl')).toBe('een-bal-en-een-doos.scene.json');
    expect(sceneFileName(scene, 'en')).toBe('a-ball-and-a-box.scene.json');
    // No Dutch name: the English one.
    expect(sceneFileName({ ...scene, name: { en: 'Only English' } }, 'nl')).toBe('only-english.scene.json');
  });

  it('says what is wrong with a damaged file', () => {
    expect(linesOf(readSceneFile('{"version": 1, "objects": ['))).toEqual([expect.stringMatching(/^\(root\): not valid JSON at line 1, column 28/)]);
    const wrong = readSceneFile(JSON.stringify({ version: 1, objects: [{ id: 'a', shape: 'cone' }] }));
    expect(wrong.ok).toBe(false);
    expect(linesOf(wrong)[0]).toBe('objects[0].shape: must be one of sphere, box, cylinder, plane, mesh, got "cone"');
    expect(linesOf(readSceneFile(JSON.stringify({ version: 2 })))).toEqual([expect.stringMatching(/^version: /)]);
    expect(linesOf(readSceneFile('{}', MAX_SCENE_FILE_BYTES + 1))).toEqual(['(root): the file is 2048 kB; a scene file is at most 2048 kB']);
  });

  it('reads the scene of a level file, with its problems under scene.', () => {
    const level = JSON.parse(readFileSync('levels/01-introduction.level.json', 'utf8'));
    const read = readSceneFile(JSON.stringify(level));
    expect(read.ok && read.scene.objects.length).toBeGreaterThan(0);
    expect(linesOf(readSceneFile(JSON.stringify({ ...level, scene: { version: 1, camera: { fov: 500 } } })))).toEqual([
      expect.stringMatching(/^scene\.camera\.fov: /),
    ]);
    expect(linesOf(readSceneFile(JSON.stringify({ ...level, scene: 3 })))).toEqual(['scene: must be an object, got 3']);
  });
});
