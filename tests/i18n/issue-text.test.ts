// The reasons a scene file is refused, as the learner reads them: in Dutch mode every line is
// Dutch (each coded reason of the schema and the JSON reader said by its msg()); in
// English they are the schema's own lines; the schema itself (what `rt validate` prints)
// stays English whatever the app speaks.
import { describe, expect, it } from 'vitest';
import { issueText } from '../../src/i18n/issue-text.ts';
import { readFileSync } from 'node:fs';
import { parseLevel } from '../../src/quest/level-schema.ts';
import { parseSceneJson } from '../../src/scene/scene-schema.ts';
import { issueLine, type Issue } from '../../src/util/issue.ts';
import { inDutch } from '../support/page-locale.ts';

/** A scene file with one of most kinds of mistake a learner's hand edit makes. */
const brokenScene = JSON.stringify({
  version: 1,
  camera: { fov: 400, position: [0, 1, 5], target: [0, 1, 5] },
  settings: { maxDepth: 'deep', supersampling: 2.5, samples: 4 },
  objects: [
    { id: 'ball', shape: 'sphere', position: [0, 1], scale: 'big', material: { color: [1, 0, 0, 1] }, colour: 'red', visible: true },
    { id: 'ball', shape: 'mesh' },
  ],
  lights: [{ id: 'lamp', type: 'torch' }],
});

function errorsOf(text: string): Issue[] {
  const result = parseSceneJson(text);
  if (result.ok) throw new Error('the broken scene was accepted');
  return result.errors;
}

describe('a broken scene file in English', () => {
  it("keeps the schema's own lines", () => {
    const errors = errorsOf(brokenScene);
    expect(errors.map(issueText)).toEqual(errors.map(issueLine));
  });
});

describe('a broken scene file in Dutch', () => {
  inDutch();

  it('says every reason in Dutch and keeps the paths and values', () => {
    const errors = errorsOf(brokenScene);
    const dutch = errors.map(issueText);
    expect(dutch).toContain('camera.fov: moet tussen 1 en 179 liggen, maar is 400');
    expect(dutch).toContain('camera.target: moet anders zijn dan camera.position');
    expect(dutch).toContain('settings.maxDepth: moet een getal zijn, maar is "deep"');
    expect(dutch).toContain('settings: onbekend veld "samples"');
    expect(dutch).toContain('settings.supersampling: moet een geheel getal zijn, maar is 2.5');
    expect(dutch).toContain('objects[0].position: moet een lijst van 3 getallen zijn, maar is een lijst met 2 elementen');
    expect(dutch).toContain('objects[0].scale: moet een lijst van 3 positieve getallen zijn, maar is "big"');
    expect(dutch).toContain('objects[0].material.color: moet een lijst van 3 getallen tussen 0 en 1 zijn, maar is een lijst met 4 elementen');
    expect(dutch).toContain('objects[0]: onbekende velden "colour", "visible"');
    expect(dutch).toContain('objects[1].id: "ball" komt twee keer voor');
    expect(dutch.some((line) => line.startsWith('objects[1].mesh: is verplicht als shape "mesh" is (een van '))).toBe(true);
    expect(dutch.some((line) => line.startsWith('lights[0].type: moet een van '))).toBe(true);
    // No English reason is left over: every code has its Dutch.
    for (const line of dutch) expect(line, line).not.toMatch(/\b(must|got|unknown|is required|is used|list of)\b/);
    // The schema, which `rt validate` prints, still speaks English.
    expect(errors.map(issueLine)).toContain('camera.fov: must be between 1 and 179, got 400');
  });

  it('says where a file stops being JSON in Dutch', () => {
    expect(errorsOf('{ "version": 1,\n  "camera": }').map(issueText)).toEqual([
      '(het geheel): geen geldige JSON op regel 2, kolom 13: verwacht werd een waarde, maar er staat "}"',
    ]);
    expect(errorsOf('{ "version": 1').map(issueText)).toEqual([
      '(het geheel): geen geldige JSON op regel 1, kolom 15: verwacht werd "," of "}", maar er staat het einde van de tekst',
    ]);
  });

  it("says a broken level's reasons in Dutch", () => {
    const level = JSON.parse(readFileSync(new URL('../../levels/02-rays-from-the-camera.level.json', import.meta.url), 'utf8')) as {
      id: string;
      tasks: { id: string; mandatory?: boolean }[];
    };
    const wrong = (change: (copy: typeof level) => void) => {
      const copy = structuredClone(level);
      change(copy);
      const result = parseLevel(copy);
      if (result.ok) throw new Error('the broken level was accepted');
      return result.errors.map(issueText);
    };
    expect(wrong((copy) => (copy.id = 'Rays 2'))).toEqual([
      'id: moet bestaan uit kleine letters en cijfers met "-" ertussen, zoals "rays-from-the-camera", maar is "Rays 2"',
    ]);
    const firstId = level.tasks[0]!.id;
    expect(
      wrong((copy) => {
        copy.tasks[1]!.id = firstId;
        for (const task of copy.tasks.slice(3)) task.mandatory = false;
      }),
    ).toEqual([`tasks[1].id: "${firstId}" komt meer dan één keer voor`, 'tasks: moet 3 tot 10 verplichte taken hebben, maar heeft er 2']);
  });
});
