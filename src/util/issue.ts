/**
 * Why a file, a link or a value cannot be used, as data: a path into the file and a reason
 * that is a code with its values. `englishReason` words a reason in English (what
 * `rt validate`, the tests and the docs quote); the app words the same reason in the
 * learner's language with one msg() per code (src/i18n/local-reason.ts), so nothing parses
 * English back out.
 *
 * Every check of a file, a link, saved progress or a lab change gives coded reasons; `worded`
 * is only for words that are already in the app's language (or are a name, or a browser's).
 */

/**
 * One problem: where (`objects[2].material.color[0]`, or `(root)` for the whole value) and
 * why; no path (null) for a problem with the file or link itself rather than with its value.
 */
export interface Issue {
  path: string | null;
  reason: Reason;
}

/** A short picture of the value a field got: never the whole of a big object. */
export type Got =
  | { kind: 'nothing' }
  | { kind: 'list'; length: number }
  | { kind: 'object' }
  /** A quoted text, a number, true, false or null: the same in every language. */
  | { kind: 'literal'; text: string };

/** What a value of the wrong type must be (zod's type names, as someone editing a file says them). */
export type ValueType = 'number' | 'string' | 'boolean' | 'object' | 'array';

/** The items of a fixed-length list: [x, y, z], [r, g, b], [width, height]. */
export type ListItems = 'numbers' | 'whole numbers' | 'positive numbers' | 'numbers between 0 and 1';

/** What the JSON reader expected where the text stops being JSON (RFC 8259's grammar). */
export type JsonExpected =
  | { kind: 'value' }
  | { kind: 'field name' }
  | { kind: 'colon' }
  | { kind: 'comma or close'; close: '}' | ']' }
  | { kind: 'closing quote, no line break' }
  | { kind: 'escape' }
  | { kind: 'closing quote' }
  | { kind: 'end of text' }
  | { kind: 'less nesting' };

export type Reason =
  | { code: 'required' }
  | { code: 'wrongType'; expected: ValueType; got: Got }
  /** A type zod names that no file field of ours has (kept so a new one still says something). */
  | { code: 'wrongTypeNamed'; expected: string; got: Got }
  /** `allowed` as quoted: one value pictured as `Got` does, or several written as they are. */
  | { code: 'notAllowed'; allowed: readonly string[]; got: Got }
  | { code: 'empty' }
  | { code: 'tooLong'; most: number }
  | { code: 'tooFewItems'; least: number; got: Got }
  | { code: 'tooManyItems'; most: number; got: Got }
  | { code: 'tooSmall'; least: number; got: Got }
  | { code: 'tooBig'; most: number; got: Got }
  | { code: 'notWhole'; got: Got }
  | { code: 'outOfRange'; lowest: number; highest: number; got: Got }
  | { code: 'notListOf'; length: number; items: ListItems; got: Got }
  | { code: 'unknownFields'; names: readonly string[] }
  | { code: 'targetIsPosition' }
  | { code: 'meshRequired'; meshes: readonly string[] }
  | { code: 'meshNotAllowed' }
  | { code: 'idReused'; id: string; uses: number }
  | { code: 'tooManyRays'; supersampling: number; lensSamples: number; timeSamples: number; rays: number; most: number }
  /** `found` is the character where the text stops being JSON, or null at its end. */
  | { code: 'fileTooLarge'; kilobytes: number; most: number }
  // The level rules (src/quest/level-rules.ts); `value`, `target`, `item`, `id` as the file writes them.
  | { code: 'usedMoreThanOnce'; value: string }
  | { code: 'mandatoryTasks'; fewest: number; most: number; count: number }
  | { code: 'solutionRequired' }
  | { code: 'hintRequired' }
  | { code: 'viewInSolution' }
  | { code: 'solutionNotAllowed'; kind: 'quiz' | 'info' }
  | { code: 'infoNotMandatory' }
  | { code: 'panelNotShown'; target: string; panel: string }
  | { code: 'controlHidden'; target: string; panel: string }
  | { code: 'noSuchItem'; item: string; ids: readonly string[] }
  | { code: 'pixelOffScreen'; item: string; columns: number; rows: number }
  | { code: 'guideNotGoalPixel'; target: string }
  | { code: 'previewRequired' }
  | { code: 'pixelRaysWithoutPixel' }
  | { code: 'lockedItemMoved'; item: string }
  | { code: 'noSuchTask'; id: string }
  // The level index (src/quest/level-index.ts).
  | { code: 'notInAnyChapter'; id: string }
  | { code: 'noLevelFile'; file: string }
  | { code: 'levelIdMismatch'; id: string; got: string }
  | { code: 'chapterMismatch'; chapter: string; got: string }
  | { code: 'notJson'; line: number; column: number; expected: JsonExpected; found: string | null }
  // Goals, their conditions and the state paths they read (src/quest/goal.ts, condition.ts, state-path.ts).
  | { code: 'appOnlyAction' }
  | { code: 'actionFields'; event: string; fields: readonly string[] }
  /** `got` is the value as JSON writes it. */
  | { code: 'comparesNumbers'; op: string; got: string }
  | { code: 'notAGoal'; fields: readonly string[]; got: Got }
  | { code: 'goalStandsAlone'; kind: string }
  | { code: 'noGoalField'; fields: readonly string[] }
  | { code: 'manyGoalFields'; fields: readonly string[]; present: readonly string[] }
  | { code: 'mixedCondition'; ops: readonly string[]; fields: readonly string[] }
  | { code: 'choiceOutOfRange'; last: number }
  | { code: 'pathStart'; path: string }
  | { code: 'pathUnreadable'; path: string; rest: string }
  /** `place` is the part of the path read so far ('' at its start). */
  | { code: 'pathIsList'; place: string; field: string }
  | { code: 'pathNoField'; field: string; place: string; fields: readonly string[] }
  | { code: 'pathNotObject'; place: string; type: PlainType; field: string }
  | { code: 'pathNotList'; place: string; step: string }
  // Guides, panels, views, evidence, option changes and ids of a level file (src/quest/level-schema.ts,
  // declared-view-schema.ts, task-evidence-schema.ts, option-changes.ts, lab-action-schema.ts, kebab-id.ts).
  | { code: 'notGuideTarget'; got: Got }
  | { code: 'panelShownAndHidden'; panel: string }
  | { code: 'panelNotListed'; panel: string }
  | { code: 'zeroDirection' }
  | { code: 'frameAndCamera' }
  | { code: 'fromWithoutFrame' }
  | { code: 'rayPathKinds'; kinds: readonly string[] }
  | { code: 'notFieldChanges'; got: Got }
  | { code: 'unknownOption'; field: string; known: readonly string[] }
  | { code: 'optionType'; field: string; expected: PlainType; got: Got }
  | { code: 'notKebabId'; got: Got }
  | { code: 'notNameText'; most: number }
  /** An id that must match a pattern (zod's own words, kept for files written against them). */
  | { code: 'notMatching'; pattern: string }
  // Saved progress, its event log and assignment links (src/quest/progress-store.ts, event-log.ts,
  // src/classroom/assignment-schema.ts).
  /** `inField`: the file is an object whose `kind` is `got`; else the file itself is `got`. */
  | { code: 'progressKind'; kind: string; inField: boolean; got: Got }
  | { code: 'progressVersion'; version: number; got: Got }
  | { code: 'earlierThanBefore' }
  | { code: 'listedTwice'; id: string }
  | { code: 'notAssignmentLevel'; id: string }
  | { code: 'notWebAddress' }
  | { code: 'notClassCode' }
  // A change the lab refuses (src/lab-state/lab-reducer.ts).
  | { code: 'noObject'; id: string }
  | { code: 'noLight'; id: string }
  | { code: 'pixelOffScreenAt'; columns: number; rows: number; column: number; row: number }
  | { code: 'bvhDepth'; most: number; got: number }
  // A survey's scale (src/classroom/survey-schema.ts).
  | { code: 'scaleSteps' }
  /** A reason already worded in the app's language (or a browser's own words, an id): shown as it is written. */
  | { code: 'worded'; text: string };

/** The JavaScript types a value of the lab's state or options can have besides objects and lists. */
export type PlainType = 'number' | 'string' | 'boolean';

export type ReasonCode = Reason['code'];

/** Text quoted in a reason: at most 40 characters, so that a 2 MB key or value is not echoed back. */
export function shortened(text: string): string {
  return text.length > 40 ? `${text.slice(0, 40)}…` : text;
}

/** The short picture of a value that a reason quotes after "got". */
export function gotOf(value: unknown): Got {
  if (value === undefined) return { kind: 'nothing' };
  if (typeof value === 'string') return { kind: 'literal', text: JSON.stringify(shortened(value)) };
  if (Array.isArray(value)) return { kind: 'list', length: value.length };
  if (value !== null && typeof value === 'object') return { kind: 'object' };
  return { kind: 'literal', text: String(value) };
}

export function englishGot(got: Got): string {
  switch (got.kind) {
    case 'nothing':
      return 'nothing';
    case 'list':
      return got.length === 1 ? 'a list of 1 item' : `a list of ${got.length} items`;
    case 'object':
      return 'an object';
    case 'literal':
      return got.text;
  }
}

/** What a value must be, for a wrong type. */
const VALUE_TYPES: Record<ValueType, string> = {
  number: 'a number',
  string: 'a string',
  boolean: 'true or false',
  object: 'an object',
  array: 'a list',
};

export function englishAllowed(allowed: readonly string[]): string {
  return allowed.length === 1 ? allowed[0]! : `one of ${allowed.join(', ')}`;
}

export function englishJsonExpected(expected: JsonExpected): string {
  switch (expected.kind) {
    case 'value':
      return 'a value';
    case 'field name':
      return 'a field name in double quotes';
    case 'colon':
      return '":"';
    case 'comma or close':
      return `"," or "${expected.close}"`;
    case 'closing quote, no line break':
      return "a closing '\"' (write a line break inside a string as \\n)";
    case 'escape':
      return 'an escape such as \\n, \\" or \\u00e9';
    case 'closing quote':
      return "a closing '\"'";
    case 'end of text':
      return 'the end of the text';
    case 'less nesting':
      return 'less deeply nested lists and objects';
  }
}

/** A reason in English, exactly as `rt validate` prints it and docs/scene-format.md quotes it. */
export function englishReason(reason: Reason): string {
  switch (reason.code) {
    case 'required':
      return 'is required';
    case 'wrongType':
      return `must be ${VALUE_TYPES[reason.expected]}, got ${englishGot(reason.got)}`;
    case 'wrongTypeNamed':
      return `must be ${reason.expected}, got ${englishGot(reason.got)}`;
    case 'notAllowed':
      return `must be ${englishAllowed(reason.allowed)}, got ${englishGot(reason.got)}`;
    case 'empty':
      return 'must not be empty';
    case 'tooLong':
      return `must be at most ${reason.most} characters long`;
    case 'tooFewItems':
      return `must have at least ${reason.least} items, got ${englishGot(reason.got)}`;
    case 'tooManyItems':
      return `must have at most ${reason.most} items, got ${englishGot(reason.got)}`;
    case 'tooSmall':
      return `must be at least ${reason.least}, got ${englishGot(reason.got)}`;
    case 'tooBig':
      return `must be at most ${reason.most}, got ${englishGot(reason.got)}`;
    case 'notWhole':
      return `must be a whole number, got ${englishGot(reason.got)}`;
    case 'outOfRange':
      return `must be between ${reason.lowest} and ${reason.highest}, got ${englishGot(reason.got)}`;
    case 'notListOf':
      return `must be a list of ${reason.length} ${reason.items}, got ${englishGot(reason.got)}`;
    case 'unknownFields':
      return `unknown field${reason.names.length > 1 ? 's' : ''} ${quotedNames(reason.names)}`;
    case 'targetIsPosition':
      return 'must differ from camera.position';
    case 'meshRequired':
      return `is required when shape is "mesh" (one of ${reason.meshes.join(', ')})`;
    case 'meshNotAllowed':
      return 'is only allowed when shape is "mesh"';
    case 'idReused':
      return `${JSON.stringify(reason.id)} is used ${reason.uses === 2 ? 'twice' : `${reason.uses} times`}`;
    case 'tooManyRays': {
      const { supersampling: s, lensSamples: n, timeSamples: k, rays, most } = reason;
      return `makes supersampling² · lensSamples² · timeSamples = ${s}² · ${n}² · ${k} = ${rays} primary rays per pixel, more than ${most}`;
    }
    case 'fileTooLarge':
      return `the file is ${reason.kilobytes} kB; a scene file is at most ${reason.most} kB`;
    case 'usedMoreThanOnce':
      return `"${reason.value}" is used more than once`;
    case 'mandatoryTasks':
      return `must have ${reason.fewest} to ${reason.most} mandatory tasks, got ${reason.count}`;
    case 'solutionRequired':
      return 'is required: the actions that complete this task ("show me" performs them)';
    case 'hintRequired':
      return 'must have at least 1 hint for a task done in the lab';
    case 'viewInSolution':
      return 'a view is the task\'s "view", not a step of its solution';
    case 'solutionNotAllowed':
      return `a ${reason.kind} task has no solution: ${reason.kind === 'quiz' ? 'its answer is in its goal' : 'it is done with Next'}`;
    case 'infoNotMandatory':
      return 'an info step is read on the way: it must be mandatory';
    case 'panelNotShown':
      return `"${reason.target}" is in the ${reason.panel} panel, which this level does not show (ui.panels)`;
    case 'controlHidden':
      return `"${reason.target}" is hidden by ui.controls.${reason.panel}`;
    case 'noSuchItem':
      return `no object or light "${reason.item}" in this level's scene (it has ${reason.ids.join(', ')})`;
    case 'pixelOffScreen':
      return `"${reason.item}" must be "column,row" inside the ${reason.columns}×${reason.rows} screen, counting from 0`;
    case 'guideNotGoalPixel':
      return `must be "${reason.target}", the pixel its goal asks for`;
    case 'previewRequired':
      return 'must include "screen-preview": a task picks a pixel, and the flat preview is where one is picked exactly';
    case 'pixelRaysWithoutPixel':
      return '"pixel-rays" needs the view to choose its pixel ("pixel": [column, row])';
    case 'lockedItemMoved':
      return `changes where "${reason.item}" is, which ui.movable locks: "show me" may only do what the learner can`;
    case 'noSuchTask':
      return `no task "${reason.id}" in this level`;
    case 'notInAnyChapter':
      return `"${reason.id}" is not a level of any chapter`;
    case 'noLevelFile':
      return `there is no file ${reason.file}`;
    case 'levelIdMismatch':
      return `must be "${reason.id}", the name index.json lists this file under, got "${reason.got}"`;
    case 'chapterMismatch':
      return `must be "${reason.chapter}", the chapter index.json lists it in, got "${reason.got}"`;
    case 'notJson':
      return `not valid JSON at line ${reason.line}, column ${reason.column}: expected ${englishJsonExpected(reason.expected)}, found ${reason.found === null ? 'the end of the text' : JSON.stringify(reason.found)}`;
    case 'appOnlyAction':
      return "a level's own view is applied by the app, not done by the learner: no goal can wait for it";
    case 'actionFields':
      return `a "${reason.event}" action ${reason.fields.length === 0 ? 'has no fields' : `has ${reason.fields.join(', ')}`}`;
    case 'comparesNumbers':
      return `"${reason.op}" compares numbers, got ${reason.got}`;
    case 'notAGoal':
      return `must be a goal: an object with one of the fields ${reason.fields.join(', ')}, got ${englishGot(reason.got)}`;
    case 'goalStandsAlone':
      return `a "${reason.kind}" goal is a task's whole goal; it cannot be inside "all" or "any"`;
    case 'noGoalField':
      return `must have one of the fields ${reason.fields.join(', ')}`;
    case 'manyGoalFields':
      return `must have only one of the fields ${reason.fields.join(', ')}, got ${reason.present.join(' and ')}`;
    case 'mixedCondition':
      return `mixes comparisons (${reason.ops.join(', ')}) with fields (${reason.fields.join(', ')})`;
    case 'choiceOutOfRange':
      return `must be the position of a choice, 0 to ${reason.last}`;
    case 'pathStart':
      return `must start with a field name, like "scene.settings.shadows", got ${JSON.stringify(reason.path)}`;
    case 'pathUnreadable':
      return `cannot read ${JSON.stringify(reason.path)} from ${JSON.stringify(reason.rest)} on: write .field, [0] or [id=name]`;
    case 'pathIsList':
      return `${reason.place} is a list: use [0], [id=…] or .length, not .${reason.field}`;
    case 'pathNoField':
      return `no field "${reason.field}"${reason.place === '' ? '' : ` in ${reason.place}`} (it has ${reason.fields.join(', ')})`;
    case 'pathNotObject':
      return `${reason.place} is a ${reason.type}: it has no field "${reason.field}"`;
    case 'pathNotList':
      return `${reason.place} is not a list, so ${reason.step} cannot select from it`;
    case 'notGuideTarget':
      return `must be a control like "tracer.supersampling" or an item like "view.item:ball" (docs/levels.md lists them), got ${englishGot(reason.got)}`;
    case 'panelShownAndHidden':
      return `the ${reason.panel} panel is in ui.panels: it cannot be hidden too`;
    case 'panelNotListed':
      return `the ${reason.panel} panel is not in ui.panels`;
    case 'zeroDirection':
      return 'must be a direction, not [0, 0, 0]';
    case 'frameAndCamera':
      return 'a view either frames things or looks through the camera, not both';
    case 'fromWithoutFrame':
      return '"from" needs a "frame" to look at';
    case 'rayPathKinds':
      return `must be kinds of ray joined by "/", from the camera's: "primary", then ${reason.kinds.join(', ')}`;
    case 'notFieldChanges':
      return `must be an object of fields to change, got ${englishGot(reason.got)}`;
    case 'unknownOption':
      return `unknown field "${reason.field}" (known: ${reason.known.join(', ')})`;
    case 'optionType':
      return `${reason.field} must be a ${reason.expected}, got ${englishGot(reason.got)}`;
    case 'notKebabId':
      return `must be lower-case letters and digits joined by "-", like "rays-from-the-camera", got ${englishGot(reason.got)}`;
    case 'notNameText':
      return `must be a text, or { "en": …, "nl": … } with a text per language (en is required; each at most ${reason.most} characters)`;
    case 'notMatching':
      return `Invalid string: must match pattern ${reason.pattern}`;
    case 'progressKind':
      return `must be "${reason.kind}" in a progress file, got ${reason.inField ? '"kind" ' : ''}${englishGot(reason.got)}`;
    case 'progressVersion':
      return `this app reads progress version ${reason.version}, got ${englishGot(reason.got)}`;
    case 'earlierThanBefore':
      return 'must not be earlier than the event before it';
    case 'listedTwice':
      return `"${reason.id}" is listed more than once`;
    case 'notAssignmentLevel':
      return `"${reason.id}" is not one of the assignment's levels`;
    case 'notWebAddress':
      return 'must be a web address that starts with http:// or https://';
    case 'notClassCode':
      return 'a class code has 1 to 32 letters, digits, - or _';
    case 'noObject':
      return `there is no object "${reason.id}"`;
    case 'noLight':
      return `there is no light "${reason.id}"`;
    case 'pixelOffScreenAt':
      return `must be inside the ${reason.columns}×${reason.rows} screen, got ${reason.column},${reason.row}`;
    case 'bvhDepth':
      return `must be a whole number from 0 to ${reason.most}, got ${reason.got}`;
    case 'scaleSteps':
      return 'max must be above min, with at most 11 steps';
    case 'worded':
      return reason.text;
    default:
      return unknownReason(reason);
  }
}

/** Field names as quoted in a reason: JSON strings, so a name with a quote in it stays one name. */
export function quotedNames(names: readonly string[]): string {
  return names.map((name) => JSON.stringify(name)).join(', ');
}

/** A new code compiles only once every formatter says it. */
function unknownReason(reason: never): never {
  throw new Error(`no wording for the reason ${JSON.stringify(reason)}`);
}

/** `path: reason` in English, the line `rt validate` prints; the bare reason when there is no path. */
export function issueLine(issue: Issue): string {
  return issue.path === null ? englishReason(issue.reason) : `${issue.path}: ${englishReason(issue.reason)}`;
}

/** An issue whose reason is already worded (in the app's language, or a name that is the same in every language). */
export function wordedIssue(path: string | null, text: string): Issue {
  return { path, reason: { code: 'worded', text } };
}
