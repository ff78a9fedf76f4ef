// Every coded reason is said by one msg() in the app (src/i18n/local-reason.ts) and by
// englishReason for `rt validate`, the tests and the docs (src/util/issue.ts). In English the
// two must be the same words, or the Dutch catalogue would translate a sentence nobody sees.
import { describe, expect, it } from 'vitest';
import { localIssue, localReason } from '../../src/i18n/local-reason.ts';
import { englishReason, issueLine, type Got, type Reason, type ReasonCode } from '../../src/util/issue.ts';
import { inDutch } from '../support/page-locale.ts';

const GOTS: Got[] = [{ kind: 'nothing' }, { kind: 'list', length: 1 }, { kind: 'list', length: 4 }, { kind: 'object' }, { kind: 'literal', text: '"wide"' }];

/** Some reasons of every code: a code missing here fails to compile. */
const SAMPLES: { [Code in ReasonCode]: Extract<Reason, { code: Code }>[] } = {
  required: [{ code: 'required' }],
  wrongType: (['number', 'string', 'boolean', 'object', 'array'] as const).flatMap((expected) =>
    GOTS.map((got) => ({ code: 'wrongType' as const, expected, got })),
  ),
  wrongTypeNamed: [{ code: 'wrongTypeNamed', expected: 'bigint', got: GOTS[4]! }],
  notAllowed: [
    { code: 'notAllowed', allowed: ['1'], got: { kind: 'literal', text: '2' } },
    { code: 'notAllowed', allowed: ['point', 'spot'], got: GOTS[0]! },
  ],
  empty: [{ code: 'empty' }],
  tooLong: [{ code: 'tooLong', most: 80 }],
  tooFewItems: [{ code: 'tooFewItems', least: 1, got: GOTS[2]! }],
  tooManyItems: [{ code: 'tooManyItems', most: 256, got: { kind: 'list', length: 257 } }],
  tooSmall: [{ code: 'tooSmall', least: 0.5, got: GOTS[0]! }],
  tooBig: [{ code: 'tooBig', most: 64, got: GOTS[1]! }],
  notWhole: [{ code: 'notWhole', got: { kind: 'literal', text: '2.5' } }],
  outOfRange: [{ code: 'outOfRange', lowest: 1, highest: 179, got: { kind: 'literal', text: '400' } }],
  notListOf: (['numbers', 'whole numbers', 'positive numbers', 'numbers between 0 and 1'] as const).map((items) => ({
    code: 'notListOf' as const,
    length: 3,
    items,
    got: GOTS[2]!,
  })),
  unknownFields: [
    { code: 'unknownFields', names: ['samples'] },
    { code: 'unknownFields', names: ['colour', 'visible'] },
  ],
  targetIsPosition: [{ code: 'targetIsPosition' }],
  meshRequired: [{ code: 'meshRequired', meshes: ['teapot', 'bunny'] }],
  meshNotAllowed: [{ code: 'meshNotAllowed' }],
  idReused: [
    { code: 'idReused', id: 'ball', uses: 2 },
    { code: 'idReused', id: 'ball', uses: 3 },
  ],
  tooManyRays: [{ code: 'tooManyRays', supersampling: 8, lensSamples: 8, timeSamples: 1, rays: 4096, most: 1024 }],
  fileTooLarge: [{ code: 'fileTooLarge', kilobytes: 3000, most: 2048 }],
  usedMoreThanOnce: [{ code: 'usedMoreThanOnce', value: 'orbit' }],
  mandatoryTasks: [{ code: 'mandatoryTasks', fewest: 3, most: 10, count: 2 }],
  solutionRequired: [{ code: 'solutionRequired' }],
  hintRequired: [{ code: 'hintRequired' }],
  viewInSolution: [{ code: 'viewInSolution' }],
  solutionNotAllowed: [
    { code: 'solutionNotAllowed', kind: 'quiz' },
    { code: 'solutionNotAllowed', kind: 'info' },
  ],
  infoNotMandatory: [{ code: 'infoNotMandatory' }],
  panelNotShown: [{ code: 'panelNotShown', target: 'light.intensity', panel: 'light' }],
  controlHidden: [{ code: 'controlHidden', target: 'tracer.pixels', panel: 'tracer' }],
  noSuchItem: [{ code: 'noSuchItem', item: 'teapot', ids: ['floor', 'ball'] }],
  pixelOffScreen: [{ code: 'pixelOffScreen', item: '9,9', columns: 6, rows: 4 }],
  guideNotGoalPixel: [{ code: 'guideNotGoalPixel', target: 'screen.pixel:3,1' }],
  previewRequired: [{ code: 'previewRequired' }],
  pixelRaysWithoutPixel: [{ code: 'pixelRaysWithoutPixel' }],
  lockedItemMoved: [{ code: 'lockedItemMoved', item: 'lamp' }],
  noSuchTask: [{ code: 'noSuchTask', id: 'no-such-task' }],
  notInAnyChapter: [{ code: 'notInAnyChapter', id: 'retired-level' }],
  noLevelFile: [{ code: 'noLevelFile', file: 'levels/03-shading.level.json' }],
  levelIdMismatch: [{ code: 'levelIdMismatch', id: 'shading', got: 'shading-copy' }],
  chapterMismatch: [{ code: 'chapterMismatch', chapter: 'light', got: 'rays' }],
  notJson: [
    { kind: 'value' },
    { kind: 'field name' },
    { kind: 'colon' },
    { kind: 'comma or close', close: '}' },
    { kind: 'comma or close', close: ']' },
    { kind: 'closing quote, no line break' },
    { kind: 'escape' },
    { kind: 'closing quote' },
    { kind: 'end of text' },
    { kind: 'less nesting' },
  ].flatMap((expected) =>
    [null, '}'].map((found) => ({
      code: 'notJson' as const,
      line: 2,
      column: 13,
      expected: expected as Extract<Reason, { code: 'notJson' }>['expected'],
      found,
    })),
  ),
  appOnlyAction: [{ code: 'appOnlyAction' }],
  actionFields: [
    { code: 'actionFields', event: 'view.orbited', fields: [] },
    { code: 'actionFields', event: 'object.added', fields: ['object'] },
  ],
  comparesNumbers: [{ code: 'comparesNumbers', op: '>=', got: '"two"' }],
  notAGoal: [{ code: 'notAGoal', fields: ['event', 'state', 'all', 'any'], got: GOTS[1]! }],
  goalStandsAlone: [{ code: 'goalStandsAlone', kind: 'quiz' }],
  noGoalField: [{ code: 'noGoalField', fields: ['event', 'state'] }],
  manyGoalFields: [{ code: 'manyGoalFields', fields: ['event', 'state'], present: ['event', 'state'] }],
  mixedCondition: [{ code: 'mixedCondition', ops: ['>='], fields: ['x'] }],
  choiceOutOfRange: [{ code: 'choiceOutOfRange', last: 2 }],
  pathStart: [{ code: 'pathStart', path: '3d' }],
  pathUnreadable: [{ code: 'pathUnreadable', path: 'scene..camera', rest: '..camera' }],
  pathIsList: [{ code: 'pathIsList', place: 'scene.objects', field: 'ball' }],
  pathNoField: [
    { code: 'pathNoField', field: 'Scene', place: '', fields: ['scene', 'rays'] },
    { code: 'pathNoField', field: 'fov2', place: 'scene.camera', fields: ['fov', 'position'] },
  ],
  pathNotObject: (['number', 'string', 'boolean'] as const).map((type) => ({ code: 'pathNotObject' as const, place: 'scene.camera.fov', type, field: 'x' })),
  pathNotList: [{ code: 'pathNotList', place: 'scene.settings', step: '[0]' }],
  notGuideTarget: [{ code: 'notGuideTarget', got: GOTS[4]! }],
  panelShownAndHidden: [{ code: 'panelShownAndHidden', panel: 'debugger' }],
  panelNotListed: [{ code: 'panelNotListed', panel: 'light' }],
  zeroDirection: [{ code: 'zeroDirection' }],
  frameAndCamera: [{ code: 'frameAndCamera' }],
  fromWithoutFrame: [{ code: 'fromWithoutFrame' }],
  rayPathKinds: [{ code: 'rayPathKinds', kinds: ['reflect', 'refract', 'shadow'] }],
  notFieldChanges: [{ code: 'notFieldChanges', got: GOTS[1]! }],
  unknownOption: [{ code: 'unknownOption', field: 'glow', known: ['showRays', 'hideNoHit'] }],
  optionType: (['number', 'string', 'boolean'] as const).map((expected) => ({ code: 'optionType' as const, field: 'depth', expected, got: GOTS[3]! })),
  notKebabId: [{ code: 'notKebabId', got: { kind: 'literal', text: '"Rays 2"' } }],
  notNameText: [{ code: 'notNameText', most: 80 }],
  notMatching: [{ code: 'notMatching', pattern: '/^[a-z]+$/' }],
  progressKind: [
    { code: 'progressKind', kind: 'ray-tracer-quest-progress', inField: false, got: GOTS[3]! },
    { code: 'progressKind', kind: 'ray-tracer-quest-progress', inField: true, got: GOTS[4]! },
  ],
  progressVersion: [{ code: 'progressVersion', version: 1, got: { kind: 'literal', text: '2' } }],
  earlierThanBefore: [{ code: 'earlierThanBefore' }],
  listedTwice: [{ code: 'listedTwice', id: 'shading' }],
  notAssignmentLevel: [{ code: 'notAssignmentLevel', id: 'shading' }],
  notWebAddress: [{ code: 'notWebAddress' }],
  notClassCode: [{ code: 'notClassCode' }],
  noObject: [{ code: 'noObject', id: 'ball' }],
  noLight: [{ code: 'noLight', id: 'lamp' }],
  pixelOffScreenAt: [{ code: 'pixelOffScreenAt', columns: 8, rows: 6, column: 9, row: 1 }],
  bvhDepth: [{ code: 'bvhDepth', most: 12, got: 13 }],
  scaleSteps: [{ code: 'scaleSteps' }],
  worded: [{ code: 'worded', text: 'a reason not coded yet' }],
};

const ALL: Reason[] = Object.values(SAMPLES).flat();

describe('coded reasons in English', () => {
  it('are the same words in the app as in rt validate, for every code', () => {
    for (const reason of ALL) expect(localReason(reason), reason.code).toBe(englishReason(reason));
  });

  it('say the lines the docs quote', () => {
    expect(englishReason(SAMPLES.outOfRange[0]!)).toBe('must be between 1 and 179, got 400');
    expect(englishReason(SAMPLES.notJson[1]!)).toBe('not valid JSON at line 2, column 13: expected a value, found "}"');
    expect(englishReason(SAMPLES.idReused[0]!)).toBe('"ball" is used twice');
    expect(englishReason(SAMPLES.unknownFields[1]!)).toBe('unknown fields "colour", "visible"');
    expect(issueLine({ path: null, reason: SAMPLES.worded[0]! })).toBe('a reason not coded yet');
    expect(localIssue({ path: '(root)', reason: SAMPLES.required[0]! })).toBe('(root): is required');
  });
});

describe('coded reasons in Dutch', () => {
  inDutch();

  it('leave no English word behind, for every code', () => {
    for (const reason of ALL.filter((each) => each.code !== 'worded' && each.code !== 'wrongTypeNamed')) {
      const dutch = localReason(reason);
      expect(dutch, reason.code).not.toBe(englishReason(reason));
      expect(dutch, dutch).not.toMatch(/\b(must|got|unknown|is required|is used|list of|expected|found|nothing|needs|has no|is hidden|in this level)\b/);
    }
  });

  it('keep worded reasons and paths as written', () => {
    expect(localIssue({ path: 'tasks[2]', reason: SAMPLES.worded[0]! })).toBe('tasks[2]: a reason not coded yet');
    expect(localIssue({ path: '(root)', reason: SAMPLES.required[0]! })).toBe('(het geheel): is verplicht');
  });
});
