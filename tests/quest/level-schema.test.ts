import { issueLine } from '../../src/util/issue.ts';
import { describe, expect, it } from 'vitest';
import { parseLevel, parseLevelJson } from '../../src/quest/level-schema.ts';
import { localize } from '../../src/quest/localized-text.ts';
import { levelFile } from '../support/quest-fixtures.ts';

type Json = Record<string, unknown>;

/** The errors of the test level after `change`; fails if it is still valid. */
function errorsOf(change: (level: Json & { tasks: Json[] }) => void): string[] {
  const result = parseLevel(levelFile(change));
  if (result.ok) throw new Error('expected the level to be rejected');
  return result.errors.map(issueLine);
}

describe('a valid level', () => {
  it('gets its defaults: mandatory, 10 points (5 when optional), no hints, no badges', () => {
    const result = parseLevel(levelFile((level) => delete level.tasks[1].hints));
    if (!result.ok) throw new Error(result.errors.map(issueLine).join('\n'));
    const [orbit, predict, , redBall] = result.level.tasks;
    expect(orbit).toMatchObject({ mandatory: true, points: 10 });
    expect(redBall).toMatchObject({ mandatory: false, points: 5 });
    expect(predict.hints).toEqual([]);
    expect(result.level.badges).toEqual([]);
    expect(result.level.scene.settings.supersampling).toBe(1);
  });

  it('keeps explicit points, including 0 for an info step', () => {
    const result = parseLevel(levelFile((level) => level.tasks.unshift({ id: 'read', title: 'Read', text: 'Read this.', points: 0, goal: { info: true } })));
    expect(result.ok && result.level.tasks[0].points).toBe(0);
  });
});

describe('texts keyed by locale', () => {
  it('are a plain English string or { en, nl }, and fall back to English', () => {
    expect(localize('Select the ball.', 'nl')).toBe('Select the ball.');
    expect(localize({ en: 'Select the ball.', nl: 'Selecteer de bal.' }, 'nl')).toBe('Selecteer de bal.');
    expect(localize({ en: 'Select the ball.' }, 'nl')).toBe('Select the ball.');
  });

  it('must have English, only known languages, and no empty text', () => {
    expect(errorsOf((level) => (level.title = { nl: 'Test' }))).toEqual(['title.en: is required']);
    expect(errorsOf((level) => (level.title = { en: 'Test', de: 'Prüfung' }))).toEqual(['title: unknown field "de"']);
    expect(errorsOf((level) => (level.title = ' '))).toEqual(['title: must not be empty']);
    expect(errorsOf((level) => (level.title = 3))).toEqual(['title: must be a string, got 3']);
  });
});

describe('field messages read `path: reason`, like scene files', () => {
  it('names missing and unknown fields and bad ids', () => {
    expect(errorsOf((level) => delete level.intro)).toEqual(['intro: is required']);
    expect(errorsOf((level) => (level.tasks[0].colour = 'red'))).toEqual(['tasks[0]: unknown field "colour"']);
    expect(errorsOf((level) => (level.id = 'Level One'))).toEqual([
      'id: must be lower-case letters and digits joined by "-", like "rays-from-the-camera", got "Level One"',
    ]);
  });

  it('reports problems in the embedded scene with their full path', () => {
    expect(errorsOf((level) => ((level.scene as { objects: Json[] }).objects[0].shape = 'cone'))).toEqual([
      'scene.objects[0].shape: must be one of sphere, box, cylinder, plane, mesh, got "cone"',
    ]);
  });

  it('says what a goal lacks when its kind cannot be told', () => {
    expect(errorsOf((level) => (level.tasks[0].goal = { happens: 'view.orbited' }))).toEqual([
      'tasks[0].goal: must have one of the fields event, state, all, any, quiz, estimate, picture, challenge, code, info',
    ]);
    expect(errorsOf((level) => (level.tasks[0].goal = { event: 'view.orbited', state: 'selection', op: '==', value: null }))).toEqual([
      'tasks[0].goal: must have only one of the fields event, state, all, any, quiz, estimate, picture, challenge, code, info, got event and state',
    ]);
    expect(errorsOf((level) => (level.tasks[0].goal = 'orbit'))).toEqual([
      'tasks[0].goal: must be a goal: an object with one of the fields event, state, all, any, quiz, estimate, picture, challenge, code, info, got "orbit"',
    ]);
  });

  it("checks each goal kind's fields where they stand, also inside all/any", () => {
    const [unknownEvent] = errorsOf((level) => (level.tasks[0].goal = { event: 'view.spun' }));
    expect(unknownEvent).toMatch(/^tasks\[0\]\.goal\.event: must be one of scene\.loaded, .*, got "view\.spun"$/);
    expect(errorsOf((level) => (level.tasks[2].goal = { all: [{ event: 'view.orbited' }, { state: 'selection', op: 'is', value: null }] }))).toEqual([
      'tasks[2].goal.all[1].op: must be one of ==, !=, >, >=, <, <=, includes, got "is"',
    ]);
    expect(errorsOf((level) => (level.tasks[2].goal = { state: 'scene.settings.supersampling', op: '>=', value: 'two' }))).toEqual([
      'tasks[2].goal.value: ">=" compares numbers, got "two"',
    ]);
    expect(errorsOf((level) => (level.tasks[0].goal = { event: 'view.orbited', times: 0 }))).toEqual(['tasks[0].goal.times: must be between 1 and 100, got 0']);
  });

  it('keeps quiz and info goals out of all/any, and quiz answers among the choices', () => {
    expect(errorsOf((level) => (level.tasks[2].goal = { any: [{ info: true }] }))).toEqual([
      'tasks[2].goal.any[0]: a "info" goal is a task\'s whole goal; it cannot be inside "all" or "any"',
    ]);
    expect(errorsOf((level) => ((level.tasks[1].goal as { quiz: Json }).quiz.answer = 3))).toEqual([
      'tasks[1].goal.quiz.answer: must be the position of a choice, 0 to 2',
    ]);
  });

  it('checks the conditions of where and with', () => {
    expect(errorsOf((level) => (level.tasks[0].goal = { event: 'view.orbited', with: { speed: 2 } }))).toEqual([
      'tasks[0].goal.with.speed: a "view.orbited" action has no fields',
    ]);
    expect(errorsOf((level) => (level.tasks[0].goal = { event: 'pixel.selected', with: { pixels: [0, 0] } }))).toEqual([
      'tasks[0].goal.with.pixels: a "pixel.selected" action has pixel',
    ]);
    expect(errorsOf((level) => (level.tasks[0].goal = { event: 'render.finished', where: { 'scene.settings.supersampling': { '>=': 2, size: 1 } } }))).toEqual([
      'tasks[0].goal.where.scene.settings.supersampling: mixes comparisons (>=) with fields (size)',
    ]);
    expect(errorsOf((level) => (level.tasks[0].goal = { event: 'render.finished', where: { 'scene.settings.supersampling': { '>': 'big' } } }))).toEqual([
      'tasks[0].goal.where.scene.settings.supersampling.>: ">" compares numbers, got "big"',
    ]);
  });

  it('checks solution actions, so that "show me" never dispatches a malformed one', () => {
    expect(errorsOf((level) => (level.tasks[0].solution = [{ type: 'pixel.selected' }]))).toEqual(['tasks[0].solution[0].pixel: is required']);
    const [unknownType] = errorsOf((level) => (level.tasks[0].solution = [{ type: 'view.spun' }]));
    expect(unknownType).toMatch(/^tasks\[0\]\.solution\[0\]\.type: must be one of scene\.loaded, .*, got "view\.spun"$/);
    expect(errorsOf((level) => (level.tasks[0].solution = [{ type: 'rays.changed', changes: { hideNoHit: 'yes', glow: 1 } }]))).toEqual([
      'tasks[0].solution[0].changes: hideNoHit must be a boolean, got "yes"',
      'tasks[0].solution[0].changes: unknown field "glow" (known: showRays, hideNoHit, hideNegligible, negligibleThreshold, transparency, radius, dynamicRadius, minRadius, maxRadius, contributionColor, colorBlindPalette, animate, animationSpeed, animatePixelByPixel, loop, showSamplePoints, colorByTime)',
    ]);
  });

  it('names guide targets it does not know', () => {
    expect(errorsOf((level) => (level.tasks[0].guide = 'tracer.samples'))).toEqual([
      'tasks[0].guide: must be a control like "tracer.supersampling" or an item like "view.item:ball" (docs/levels.md lists them), got "tracer.samples"',
    ]);
  });

  it('checks ui.controls against the panels and their controls', () => {
    expect(errorsOf((level) => (level.ui = { panels: ['object'], controls: { tracer: ['pixels'], object: ['colour'] } }))).toEqual([
      'ui.controls.tracer: the tracer panel is not in ui.panels',
      'ui.controls.object[0]: must be one of color, ambient, diffuse, specular, shininess, transparent, refractive-index, presets, roughness, glossy-samples, velocity, got "colour"',
    ]);
  });

  it('takes ui.movable: items of the scene or the camera, each once, with the gizmo shown', () => {
    const ok = parseLevel(levelFile((level) => (level.ui = { panels: ['object', 'tracer', 'render', 'gizmo'], movable: ['ball', 'camera'] })));
    expect(ok.ok && ok.level.ui.movable).toEqual(['ball', 'camera']);
    // Without it, nothing is locked.
    const open = parseLevel(levelFile());
    expect(open.ok && open.level.ui.movable).toBeUndefined();
    expect(errorsOf((level) => (level.ui = { panels: ['object', 'tracer', 'render', 'gizmo'], movable: ['box', 'ball', 'ball'] }))).toEqual([
      'ui.movable[2]: "ball" is used more than once',
      'ui.movable[0]: must be one of ball, lamp, camera, got "box"',
    ]);
    expect(errorsOf((level) => (level.ui = { panels: ['object', 'tracer', 'render'], movable: ['ball'] }))).toEqual([
      'ui.movable: the gizmo panel is not in ui.panels',
    ]);
    expect(errorsOf((level) => (level.ui = { panels: ['object', 'tracer', 'render', 'gizmo'], movable: [] }))).toEqual([
      'ui.movable: must have at least 1 items, got a list of 0 items',
    ]);
  });

  it('has "show me" keep to ui.movable: a solution places and deletes only movable items, but may change a locked one’s other fields', () => {
    const locking = (solution: Json[]) => (level: Json & { tasks: Json[] }) => {
      level.ui = { panels: ['object', 'tracer', 'render', 'gizmo'], movable: ['ball'] };
      level.tasks[3]!.solution = solution;
    };
    const allowed = [
      { type: 'object.changed', id: 'ball', changes: { position: [1, 0.5, 0] } },
      { type: 'material.changed', id: 'ball', changes: { color: [1, 0, 0] } },
      { type: 'light.changed', id: 'lamp', changes: { intensity: 2 } },
      { type: 'camera.changed', changes: { fov: 30 } },
    ];
    expect(parseLevel(levelFile(locking(allowed))).ok).toBe(true);
    expect(
      errorsOf(
        locking([
          { type: 'light.changed', id: 'lamp', changes: { position: [0, 4, 0] } },
          { type: 'camera.changed', changes: { target: [0, 0, 0] } },
          { type: 'light.deleted', id: 'lamp' },
          { type: 'material.changed', id: 'ball', changes: { color: [1, 0, 0] } },
        ]),
      ),
    ).toEqual([
      'tasks[3].solution[0]: changes where "lamp" is, which ui.movable locks: "show me" may only do what the learner can',
      'tasks[3].solution[1]: changes where "camera" is, which ui.movable locks: "show me" may only do what the learner can',
      'tasks[3].solution[2]: changes where "lamp" is, which ui.movable locks: "show me" may only do what the learner can',
    ]);
  });

  it('takes a reason for leaving the debugger out, but not for a panel it shows', () => {
    const reason = { en: 'Rays come in the next level.', nl: 'Stralen komen in het volgende level.' };
    const ok = parseLevel(levelFile((level) => ((level.ui as Json).hidden = { debugger: reason })));
    expect(ok.ok && ok.level.ui.hidden).toEqual({ debugger: reason });
    expect(errorsOf((level) => (level.ui = { panels: ['object', 'tracer', 'render', 'debugger'], hidden: { debugger: reason } }))).toEqual([
      'ui.hidden.debugger: the debugger panel is in ui.panels: it cannot be hidden too',
    ]);
  });

  it('gives one line for text that is not JSON', () => {
    const notJson = parseLevelJson('{ "version": 1, }');
    expect(notJson.ok ? [] : notJson.errors.map(issueLine)).toEqual([
      '(root): not valid JSON at line 1, column 17: expected a field name in double quotes, found "}"',
    ]);
  });
});

describe('rules across fields (once every field is valid)', () => {
  it('wants 3 to 10 mandatory tasks', () => {
    expect(errorsOf((level) => (level.tasks[0].mandatory = false))).toEqual(['tasks: must have 3 to 10 mandatory tasks, got 2']);
  });

  it('wants unique task ids', () => {
    expect(errorsOf((level) => (level.tasks[4].id = 'orbit'))).toEqual(['tasks[4].id: "orbit" is used more than once']);
  });

  it('wants a solution and a hint for tasks done in the lab, and none for quiz and info tasks', () => {
    expect(
      errorsOf((level) => {
        delete level.tasks[0].solution;
        level.tasks[0].hints = [];
        level.tasks[1].solution = [{ type: 'view.orbited' }];
      }),
    ).toEqual([
      'tasks[0].solution: is required: the actions that complete this task ("show me" performs them)',
      'tasks[0].hints: must have at least 1 hint for a task done in the lab',
      'tasks[1].solution: a quiz task has no solution: its answer is in its goal',
    ]);
    expect(errorsOf((level) => level.tasks.push({ id: 'read', title: 'Read', text: 'Read.', mandatory: false, goal: { info: true } }))).toEqual([
      'tasks[5].mandatory: an info step is read on the way: it must be mandatory',
    ]);
  });

  it('checks state paths against the state the level starts in', () => {
    expect(errorsOf((level) => (level.tasks[2].goal = { state: 'scene.settings.supersample', op: '>=', value: 2 }))).toEqual([
      'tasks[2].goal.state: no field "supersample" in scene.settings (it has shadows, maxDepth, background, supersampling, samplePattern, imageSize, dithering, encoding, lightTypes, timeSamples, timePattern, integrator, pathSamples, pixelSampling, bounceSampling, lightSampling, russianRoulette, exposure)',
    ]);
    expect(errorsOf((level) => (level.tasks[2].goal = { event: 'render.finished', where: { 'scene.objects.color': [1, 0, 0] } }))).toEqual([
      'tasks[2].goal.where.scene.objects.color: scene.objects is a list: use [0], [id=…] or .length, not .color',
    ]);
    expect(
      errorsOf(
        (level) =>
          (level.tasks[2].goal = {
            any: [
              { state: 'selection.kind', op: '==', value: 'object' },
              { state: 'scene..x', op: '==', value: 1 },
            ],
          }),
      ),
    ).toEqual(['tasks[2].goal.any[1].state: cannot read "scene..x" from "..x" on: write .field, [0] or [id=name]']);
  });

  it('accepts paths the starting state cannot show: ids added later, optional fields, selections', () => {
    const result = parseLevel(
      levelFile((level) => {
        level.tasks[2].goal = {
          all: [
            { state: 'scene.objects[id=sphere-1].material.color', op: '==', value: [1, 0, 0] },
            { state: 'scene.objects[id=ball].name', op: '==', value: 'Ball' },
            { state: 'selection.id', op: '==', value: 'ball' },
            { state: 'selectedPixel[0]', op: '==', value: 0 },
            { state: 'scene.lights.length', op: '>', value: 1 },
          ],
        };
      }),
    );
    expect(result.ok ? [] : result.errors.map(issueLine)).toEqual([]);
  });

  it('wants a guide the learner can see: a shown panel, an allowed control, an item in the scene', () => {
    expect(errorsOf((level) => (level.tasks[0].guide = 'rays.hide-no-hit'))).toEqual([
      'tasks[0].guide: "rays.hide-no-hit" is in the rays panel, which this level does not show (ui.panels)',
    ]);
    expect(errorsOf((level) => (level.ui = { panels: ['object', 'tracer', 'render'], controls: { tracer: ['pixels'] } }))).toEqual([
      'tasks[2].guide: "tracer.supersampling" is hidden by ui.controls.tracer',
    ]);
    expect(errorsOf((level) => (level.tasks[0].guide = 'view.item:box'))).toEqual([
      'tasks[0].guide: no object or light "box" in this level\'s scene (it has ball, lamp)',
    ]);
    expect(errorsOf((level) => (level.tasks[0].guide = 'screen.pixel:4,0'))).toEqual([
      'tasks[0].guide: "4,0" must be "column,row" inside the 4×3 screen, counting from 0',
    ]);
  });

  it('wants a task that picks a pixel to ring that pixel, in a level with the flat pixel preview', () => {
    const picking = (level: Json & { tasks: Json[] }, guide: string) => {
      level.tasks[0].goal = { event: 'pixel.selected', with: { pixel: [1, 2] } };
      level.tasks[0].solution = [{ type: 'pixel.selected', pixel: [1, 2] }];
      level.tasks[0].guide = guide;
    };
    expect(errorsOf((level) => picking(level, 'screen.pixel:2,1'))).toEqual([
      'tasks[0].guide: must be "screen.pixel:1,2", the pixel its goal asks for',
      'ui.panels: must include "screen-preview": a task picks a pixel, and the flat preview is where one is picked exactly',
    ]);
    const result = parseLevel(
      levelFile((level) => {
        picking(level, 'screen.pixel:1,2');
        (level.ui as { panels: string[] }).panels.push('screen-preview');
      }),
    );
    expect(result.ok ? [] : result.errors.map(issueLine)).toEqual([]);
  });

  it("wants a task's evidence to name rays by their way from the camera, and things and a pixel the scene has", () => {
    const valid = parseLevel(
      levelFile(
        (level) =>
          (level.tasks[0].evidence = { objects: ['ball', 'lamp'], rays: { pixel: [3, 2], paths: ['primary', 'primary/shadow', 'primary/reflect/light'] } }),
      ),
    );
    expect(valid.ok ? valid.level.tasks[0]!.evidence : valid.errors).toEqual({
      objects: ['ball', 'lamp'],
      rays: { pixel: [3, 2], paths: ['primary', 'primary/shadow', 'primary/reflect/light'] },
    });
    expect(errorsOf((level) => (level.tasks[0].evidence = { objects: ['box'], rays: { pixel: [4, 0], paths: ['shadow', 'primary/bounce'] } }))).toEqual([
      'tasks[0].evidence.rays.paths[0]: must be kinds of ray joined by "/", from the camera\'s: "primary", then reflect, refract, shadow, light, area-light, area-shadow',
      'tasks[0].evidence.rays.paths[1]: must be kinds of ray joined by "/", from the camera\'s: "primary", then reflect, refract, shadow, light, area-light, area-shadow',
    ]);
    expect(errorsOf((level) => (level.tasks[0].evidence = { objects: ['box'], rays: { pixel: [4, 0], paths: ['primary'] } }))).toEqual([
      'tasks[0].evidence.objects[0]: no object or light "box" in this level\'s scene (it has ball, lamp)',
      'tasks[0].evidence.rays.pixel: "4,0" must be "column,row" inside the 4×3 screen, counting from 0',
    ]);
  });

  it('wants level badges to name tasks of the level', () => {
    expect(errorsOf((level) => (level.badges = [{ id: 'painter', title: 'Painter', text: 'You painted.', tasks: ['red-ball', 'paint'] }]))).toEqual([
      'badges[0].tasks[1]: no task "paint" in this level',
    ]);
  });
});
