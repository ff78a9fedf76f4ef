import { msg, str } from '@lit/localize';
import type { Got, Issue, JsonExpected, ListItems, PlainType, Reason, ValueType } from '../util/issue.ts';
import { quotedNames } from '../util/issue.ts';

/**
 * A coded reason (src/util/issue.ts) in the app's language: one msg() per code, whose
 * English is word for word what `englishReason` says (tests/i18n/local-reason.test.ts
 * checks every code). Ids, field names and the values quoted stay as the file writes them.
 */
export function localReason(reason: Reason): string {
  switch (reason.code) {
    case 'required':
      return msg('is required');
    case 'wrongType':
      return msg(str`must be ${localValueType(reason.expected)}, got ${localGot(reason.got)}`);
    case 'wrongTypeNamed':
      return msg(str`must be ${reason.expected}, got ${localGot(reason.got)}`);
    case 'notAllowed': {
      const allowed = reason.allowed.length === 1 ? reason.allowed[0]! : msg(str`one of ${reason.allowed.join(', ')}`);
      return msg(str`must be ${allowed}, got ${localGot(reason.got)}`);
    }
    case 'empty':
      return msg('must not be empty');
    case 'tooLong':
      return msg(str`must be at most ${reason.most} characters long`);
    case 'tooFewItems':
      return msg(str`must have at least ${reason.least} items, got ${localGot(reason.got)}`);
    case 'tooManyItems':
      return msg(str`must have at most ${reason.most} items, got ${localGot(reason.got)}`);
    case 'tooSmall':
      return msg(str`must be at least ${reason.least}, got ${localGot(reason.got)}`);
    case 'tooBig':
      return msg(str`must be at most ${reason.most}, got ${localGot(reason.got)}`);
    case 'notWhole':
      return msg(str`must be ${msg('a whole number')}, got ${localGot(reason.got)}`);
    case 'outOfRange':
      return msg(str`must be between ${reason.lowest} and ${reason.highest}, got ${localGot(reason.got)}`);
    case 'notListOf':
      return msg(str`must be ${localList(reason.length, reason.items)}, got ${localGot(reason.got)}`);
    case 'unknownFields': {
      const names = quotedNames(reason.names);
      return reason.names.length > 1 ? msg(str`unknown fields ${names}`) : msg(str`unknown field ${names}`);
    }
    case 'targetIsPosition':
      return msg('must differ from camera.position');
    case 'meshRequired':
      return msg(str`is required when shape is "mesh" (one of ${reason.meshes.join(', ')})`);
    case 'meshNotAllowed':
      return msg('is only allowed when shape is "mesh"');
    case 'idReused': {
      const id = JSON.stringify(reason.id);
      return reason.uses === 2 ? msg(str`${id} is used twice`) : msg(str`${id} is used ${reason.uses} times`);
    }
    case 'tooManyRays': {
      // The formula's names are the file's fields: they stay as written.
      const { supersampling: s, lensSamples: n, timeSamples: k, rays, most } = reason;
      const sum = `supersampling² · lensSamples² · timeSamples = ${s}² · ${n}² · ${k}`;
      return msg(str`makes ${sum} = ${rays} primary rays per pixel, more than ${most}`);
    }
    case 'fileTooLarge':
      return msg(str`the file is ${reason.kilobytes} kB; a scene file is at most ${reason.most} kB`);
    case 'usedMoreThanOnce': {
      const value = `"${reason.value}"`;
      return msg(str`${value} is used more than once`);
    }
    case 'mandatoryTasks':
      return msg(str`must have ${reason.fewest} to ${reason.most} mandatory tasks, got ${reason.count}`);
    case 'solutionRequired':
      return msg('is required: the actions that complete this task ("show me" performs them)');
    case 'hintRequired':
      return msg('must have at least 1 hint for a task done in the lab');
    case 'viewInSolution':
      return msg('a view is the task\'s "view", not a step of its solution');
    case 'solutionNotAllowed':
      return reason.kind === 'quiz' ? msg('a quiz task has no solution: its answer is in its goal') : msg('a info task has no solution: it is done with Next');
    case 'infoNotMandatory':
      return msg('an info step is read on the way: it must be mandatory');
    case 'panelNotShown': {
      const target = `"${reason.target}"`;
      return msg(str`${target} is in the ${reason.panel} panel, which this level does not show (ui.panels)`);
    }
    case 'controlHidden': {
      const target = `"${reason.target}"`;
      return msg(str`${target} is hidden by ui.controls.${reason.panel}`);
    }
    case 'noSuchItem': {
      const item = `"${reason.item}"`;
      return msg(str`no object or light ${item} in this level's scene (it has ${reason.ids.join(', ')})`);
    }
    case 'pixelOffScreen': {
      const item = `"${reason.item}"`;
      return msg(str`${item} must be "column,row" inside the ${reason.columns}×${reason.rows} screen, counting from 0`);
    }
    case 'guideNotGoalPixel': {
      const target = `"${reason.target}"`;
      return msg(str`must be ${target}, the pixel its goal asks for`);
    }
    case 'previewRequired':
      return msg('must include "screen-preview": a task picks a pixel, and the flat preview is where one is picked exactly');
    case 'pixelRaysWithoutPixel':
      return msg('"pixel-rays" needs the view to choose its pixel ("pixel": [column, row])');
    case 'lockedItemMoved': {
      const item = `"${reason.item}"`;
      return msg(str`changes where ${item} is, which ui.movable locks: "show me" may only do what the learner can`);
    }
    case 'noSuchTask': {
      const id = `"${reason.id}"`;
      return msg(str`no task ${id} in this level`);
    }
    case 'notInAnyChapter': {
      const id = `"${reason.id}"`;
      return msg(str`${id} is not a level of any chapter`);
    }
    case 'noLevelFile':
      return msg(str`there is no file ${reason.file}`);
    case 'levelIdMismatch': {
      const [id, got] = [`"${reason.id}"`, `"${reason.got}"`];
      return msg(str`must be ${id}, the name index.json lists this file under, got ${got}`);
    }
    case 'chapterMismatch': {
      const [chapter, got] = [`"${reason.chapter}"`, `"${reason.got}"`];
      return msg(str`must be ${chapter}, the chapter index.json lists it in, got ${got}`);
    }
    case 'notJson': {
      const { line, column } = reason;
      const found = reason.found === null ? msg('the end of the text') : JSON.stringify(reason.found);
      return msg(str`not valid JSON at line ${line}, column ${column}: expected ${localJsonExpected(reason.expected)}, found ${found}`);
    }
    case 'appOnlyAction':
      return msg("a level's own view is applied by the app, not done by the learner: no goal can wait for it");
    case 'actionFields': {
      const event = `"${reason.event}"`;
      return reason.fields.length === 0 ? msg(str`a ${event} action has no fields`) : msg(str`a ${event} action has ${reason.fields.join(', ')}`);
    }
    case 'comparesNumbers': {
      const op = `"${reason.op}"`;
      return msg(str`${op} compares numbers, got ${reason.got}`);
    }
    case 'notAGoal':
      return msg(str`must be a goal: an object with one of the fields ${reason.fields.join(', ')}, got ${localGot(reason.got)}`);
    case 'goalStandsAlone': {
      const kind = `"${reason.kind}"`;
      return msg(str`a ${kind} goal is a task's whole goal; it cannot be inside "all" or "any"`);
    }
    case 'noGoalField':
      return msg(str`must have one of the fields ${reason.fields.join(', ')}`);
    case 'manyGoalFields': {
      const present = reason.present.join(` ${msg('and')} `);
      return msg(str`must have only one of the fields ${reason.fields.join(', ')}, got ${present}`);
    }
    case 'mixedCondition':
      return msg(str`mixes comparisons (${reason.ops.join(', ')}) with fields (${reason.fields.join(', ')})`);
    case 'choiceOutOfRange':
      return msg(str`must be the position of a choice, 0 to ${reason.last}`);
    case 'pathStart':
      return msg(str`must start with a field name, like "scene.settings.shadows", got ${JSON.stringify(reason.path)}`);
    case 'pathUnreadable': {
      const [path, rest] = [JSON.stringify(reason.path), JSON.stringify(reason.rest)];
      return msg(str`cannot read ${path} from ${rest} on: write .field, [0] or [id=name]`);
    }
    case 'pathIsList':
      return msg(str`${reason.place} is a list: use [0], [id=…] or .length, not .${reason.field}`);
    case 'pathNoField': {
      const [field, fields] = [`"${reason.field}"`, reason.fields.join(', ')];
      return reason.place === '' ? msg(str`no field ${field} (it has ${fields})`) : msg(str`no field ${field} in ${reason.place} (it has ${fields})`);
    }
    case 'pathNotObject': {
      const field = `"${reason.field}"`;
      return msg(str`${reason.place} is ${localPlainType(reason.type)}: it has no field ${field}`);
    }
    case 'pathNotList':
      return msg(str`${reason.place} is not a list, so ${reason.step} cannot select from it`);
    case 'notGuideTarget':
      return msg(str`must be a control like "tracer.supersampling" or an item like "view.item:ball" (docs/levels.md lists them), got ${localGot(reason.got)}`);
    case 'panelShownAndHidden':
      return msg(str`the ${reason.panel} panel is in ui.panels: it cannot be hidden too`);
    case 'panelNotListed':
      return msg(str`the ${reason.panel} panel is not in ui.panels`);
    case 'zeroDirection':
      return msg('must be a direction, not [0, 0, 0]');
    case 'frameAndCamera':
      return msg('a view either frames things or looks through the camera, not both');
    case 'fromWithoutFrame':
      return msg('"from" needs a "frame" to look at');
    case 'rayPathKinds':
      return msg(str`must be kinds of ray joined by "/", from the camera's: "primary", then ${reason.kinds.join(', ')}`);
    case 'notFieldChanges':
      return msg(str`must be an object of fields to change, got ${localGot(reason.got)}`);
    case 'unknownOption': {
      const field = `"${reason.field}"`;
      return msg(str`unknown field ${field} (known: ${reason.known.join(', ')})`);
    }
    case 'optionType':
      return msg(str`${reason.field} must be ${localPlainType(reason.expected)}, got ${localGot(reason.got)}`);
    case 'notKebabId': {
      // The example is an id, the same in every language.
      const example = 'rays-from-the-camera';
      return msg(str`must be lower-case letters and digits joined by "-", like "${example}", got ${localGot(reason.got)}`);
    }
    case 'notNameText':
      return msg(str`must be a text, or { "en": …, "nl": … } with a text per language (en is required; each at most ${reason.most} characters)`);
    case 'notMatching':
      return msg(str`Invalid string: must match pattern ${reason.pattern}`);
    case 'progressKind': {
      const [kind, got] = [`"${reason.kind}"`, `${reason.inField ? '"kind" ' : ''}${localGot(reason.got)}`];
      return msg(str`must be ${kind} in a progress file, got ${got}`);
    }
    case 'progressVersion':
      return msg(str`this app reads progress version ${reason.version}, got ${localGot(reason.got)}`);
    case 'earlierThanBefore':
      return msg('must not be earlier than the event before it');
    case 'listedTwice': {
      const id = `"${reason.id}"`;
      return msg(str`${id} is listed more than once`);
    }
    case 'notAssignmentLevel': {
      const id = `"${reason.id}"`;
      return msg(str`${id} is not one of the assignment's levels`);
    }
    case 'notWebAddress':
      return msg('must be a web address that starts with http:// or https://');
    case 'notClassCode':
      return msg('a class code has 1 to 32 letters, digits, - or _');
    case 'noObject': {
      const id = `"${reason.id}"`;
      return msg(str`there is no object ${id}`);
    }
    case 'noLight': {
      const id = `"${reason.id}"`;
      return msg(str`there is no light ${id}`);
    }
    case 'pixelOffScreenAt': {
      const got = `${reason.column},${reason.row}`;
      return msg(str`must be inside the ${reason.columns}×${reason.rows} screen, got ${got}`);
    }
    case 'bvhDepth':
      return msg(str`must be a whole number from 0 to ${reason.most}, got ${reason.got}`);
    case 'scaleSteps':
      return msg('max must be above min, with at most 11 steps');
    case 'worded':
      return reason.text;
    default:
      return unknownReason(reason);
  }
}

/** A new code compiles only once it has its msg(). */
function unknownReason(reason: never): never {
  throw new Error(`no wording for the reason ${JSON.stringify(reason)}`);
}

/** `path: reason` in the app's language; paths are field names of the file and stay as written. */
export function localIssue(issue: Issue): string {
  const reason = localReason(issue.reason);
  if (issue.path === null) return reason;
  return `${issue.path === '(root)' ? msg('(root)') : issue.path}: ${reason}`;
}

function localGot(got: Got): string {
  switch (got.kind) {
    case 'nothing':
      return msg('nothing');
    case 'list':
      return got.length === 1 ? msg('a list of 1 item') : msg(str`a list of ${got.length} items`);
    case 'object':
      return msg('an object');
    case 'literal':
      return got.text;
  }
}

function localValueType(type: ValueType): string {
  switch (type) {
    case 'number':
      return msg('a number');
    case 'string':
      return msg('a string');
    case 'boolean':
      return msg('true or false');
    case 'object':
      return msg('an object');
    case 'array':
      return msg('a list');
  }
}

function localPlainType(type: PlainType): string {
  switch (type) {
    case 'number':
      return msg('a number');
    case 'string':
      return msg('a string');
    case 'boolean':
      return msg('a boolean');
  }
}

function localList(count: number, items: ListItems): string {
  switch (items) {
    case 'numbers':
      return msg(str`a list of ${count} numbers`);
    case 'whole numbers':
      return msg(str`a list of ${count} whole numbers`);
    case 'positive numbers':
      return msg(str`a list of ${count} positive numbers`);
    case 'numbers between 0 and 1':
      return msg(str`a list of ${count} numbers between 0 and 1`);
  }
}

function localJsonExpected(expected: JsonExpected): string {
  switch (expected.kind) {
    case 'value':
      return msg('a value');
    case 'field name':
      return msg('a field name in double quotes');
    case 'colon':
      return '":"';
    case 'comma or close': {
      const [one, other] = [',', expected.close];
      return msg(str`"${one}" or "${other}"`);
    }
    case 'closing quote, no line break':
      return msg("a closing '\"' (write a line break inside a string as \\n)");
    case 'escape':
      return msg('an escape such as \\n, \\" or \\u00e9');
    case 'closing quote':
      return msg("a closing '\"'");
    case 'end of text':
      return msg('the end of the text');
    case 'less nesting':
      return msg('less deeply nested lists and objects');
  }
}
