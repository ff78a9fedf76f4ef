import { msg, str } from '@lit/localize';
import { KINDS, translatedOrNull, value, type Rule } from './issue-rules.ts';

/**
 * The reasons a level file and the level index are refused for, beyond the scene schema's:
 * the level rules that look at several fields (src/quest/level-rules.ts), goals and their
 * conditions and state paths (goal.ts, condition.ts, state-path.ts), views, option changes,
 * guides, and the index (level-schema.ts, declared-view-schema.ts, option-changes.ts,
 * lab-action-schema.ts, level-index.ts), said again in the app's language. Ids, field
 * names and the values quoted stay as the file writes them.
 */

/** "a string", "a number", "a boolean": the type names the option and path checks quote. */
const typeName = (kind: string) => translatedOrNull(KINDS, kind);

/** Goal kinds joined by " and " (chooseByField in goal.ts). */
const joinedByAnd = (names: string) => names.split(' and ').join(` ${msg('and')} `);

export const LEVEL_REASONS: readonly Rule[] = [
  // Level rules (level-rules.ts).
  [
    /^is required: the actions that complete this task \("show me" performs them\)$/,
    () => msg('is required: the actions that complete this task ("show me" performs them)'),
  ],
  [/^must have at least 1 hint for a task done in the lab$/, () => msg('must have at least 1 hint for a task done in the lab')],
  [/^a view is the task's "view", not a step of its solution$/, () => msg('a view is the task\'s "view", not a step of its solution')],
  [/^a quiz task has no solution: its answer is in its goal$/, () => msg('a quiz task has no solution: its answer is in its goal')],
  [/^a info task has no solution: it is done with Next$/, () => msg('a info task has no solution: it is done with Next')],
  [/^an info step is read on the way: it must be mandatory$/, () => msg('an info step is read on the way: it must be mandatory')],
  [
    /^(".*") is in the (\S+) panel, which this level does not show \(ui\.panels\)$/,
    (target, panel) => msg(str`${target} is in the ${panel} panel, which this level does not show (ui.panels)`),
  ],
  [/^(".*") is hidden by ui\.controls\.(\S+)$/, (target, panel) => msg(str`${target} is hidden by ui.controls.${panel}`)],
  [
    /^no object or light (".*") in this level's scene \(it has (.*)\)$/,
    (item, ids) => msg(str`no object or light ${item} in this level's scene (it has ${ids})`),
  ],
  [
    /^(".*") must be "column,row" inside the (\d+)×(\d+) screen, counting from 0$/,
    (item, columns, rows) => msg(str`${item} must be "column,row" inside the ${columns}×${rows} screen, counting from 0`),
  ],
  [/^must be (".*"), the pixel its goal asks for$/, (target) => msg(str`must be ${target}, the pixel its goal asks for`)],
  [
    /^must include "screen-preview": a task picks a pixel, and the flat preview is where one is picked exactly$/,
    () => msg('must include "screen-preview": a task picks a pixel, and the flat preview is where one is picked exactly'),
  ],
  [
    /^"pixel-rays" needs the view to choose its pixel \("pixel": \[column, row\]\)$/,
    () => msg('"pixel-rays" needs the view to choose its pixel ("pixel": [column, row])'),
  ],
  [/^no task (".*") in this level$/, (id) => msg(str`no task ${id} in this level`)],

  // Guides and panels (level-schema.ts).
  [
    /^must be a control like "tracer\.supersampling" or an item like "view\.item:ball" \(docs\/levels\.md lists them\), got (.+)$/,
    (got) => msg(str`must be a control like "tracer.supersampling" or an item like "view.item:ball" (docs/levels.md lists them), got ${value(got)}`),
  ],
  [/^the (\S+) panel is not in ui\.panels$/, (panel) => msg(str`the ${panel} panel is not in ui.panels`)],
  [/^the (\S+) panel is in ui\.panels: it cannot be hidden too$/, (panel) => msg(str`the ${panel} panel is in ui.panels: it cannot be hidden too`)],

  // Goals and their conditions (goal.ts, condition.ts).
  [
    /^a level's own view is applied by the app, not done by the learner: no goal can wait for it$/,
    () => msg("a level's own view is applied by the app, not done by the learner: no goal can wait for it"),
  ],
  [/^a (".*") action has no fields$/, (event) => msg(str`a ${event} action has no fields`)],
  [/^a (".*") action has (.+)$/, (event, fields) => msg(str`a ${event} action has ${fields}`)],
  [/^(".*") compares numbers, got (.+)$/, (op, got) => msg(str`${op} compares numbers, got ${got}`)],
  [
    /^must be a goal: an object with one of the fields (.+), got (.+)$/,
    (names, got) => msg(str`must be a goal: an object with one of the fields ${names}, got ${value(got)}`),
  ],
  [
    /^a (".*") goal is a task's whole goal; it cannot be inside "all" or "any"$/,
    (kind) => msg(str`a ${kind} goal is a task's whole goal; it cannot be inside "all" or "any"`),
  ],
  [/^must have only one of the fields (.+), got (.+)$/, (names, present) => msg(str`must have only one of the fields ${names}, got ${joinedByAnd(present)}`)],
  [/^must have one of the fields (.+)$/, (names) => msg(str`must have one of the fields ${names}`)],
  [/^mixes comparisons \((.*)\) with fields \((.*)\)$/, (ops, fields) => msg(str`mixes comparisons (${ops}) with fields (${fields})`)],

  // State paths (state-path.ts): the path and its pieces are quoted as written.
  [
    /^must start with a field name, like "scene\.settings\.shadows", got (.+)$/,
    (got) => msg(str`must start with a field name, like "scene.settings.shadows", got ${got}`),
  ],
  [
    /^cannot read (".*") from (".*") on: write \.field, \[0\] or \[id=name\]$/,
    (path, rest) => msg(str`cannot read ${path} from ${rest} on: write .field, [0] or [id=name]`),
  ],
  [
    /^(\S*) is a list: use \[0\], \[id=…\] or \.length, not \.(\S+)$/,
    (place, field) => msg(str`${place} is a list: use [0], [id=…] or .length, not .${field}`),
  ],
  [/^no field (".*") in (\S+) \(it has (.*)\)$/, (field, place, fields) => msg(str`no field ${field} in ${place} (it has ${fields})`)],
  [/^no field (".*") \(it has (.*)\)$/, (field, fields) => msg(str`no field ${field} (it has ${fields})`)],
  [
    /^(\S*) is (a \w+): it has no field (".*")$/,
    (place, kind, field) => {
      const type = typeName(kind);
      return type === null ? null : msg(str`${place} is ${type}: it has no field ${field}`);
    },
  ],
  [/^(\S*) is not a list, so (\[.*\]) cannot select from it$/, (place, step) => msg(str`${place} is not a list, so ${step} cannot select from it`)],

  // Views (declared-view-schema.ts), evidence (task-evidence-schema.ts) and option changes (option-changes.ts, lab-action-schema.ts).
  [/^must be a direction, not \[0, 0, 0\]$/, () => msg('must be a direction, not [0, 0, 0]')],
  [/^a view either frames things or looks through the camera, not both$/, () => msg('a view either frames things or looks through the camera, not both')],
  [/^"from" needs a "frame" to look at$/, () => msg('"from" needs a "frame" to look at')],
  [
    /^must be kinds of ray joined by "\/", from the camera's: "primary", then (.+)$/,
    (kinds) => msg(str`must be kinds of ray joined by "/", from the camera's: "primary", then ${kinds}`),
  ],
  [/^must be an object of fields to change, got (.+)$/, (got) => msg(str`must be an object of fields to change, got ${value(got)}`)],
  [/^unknown field (".*") \(known: (.*)\)$/, (field, known) => msg(str`unknown field ${field} (known: ${known})`)],
  [
    /^(\S+) must be (a \w+), got (.+)$/,
    (field, kind, got) => {
      const type = typeName(kind);
      return type === null ? null : msg(str`${field} must be ${type}, got ${value(got)}`);
    },
  ],

  // The level index (level-index.ts).
  [/^there is no file (levels\/\S+)$/, (file) => msg(str`there is no file ${file}`)],
  [
    /^must be (".*"), the name index\.json lists this file under, got (".*")$/,
    (id, got) => msg(str`must be ${id}, the name index.json lists this file under, got ${got}`),
  ],
  [
    /^must be (".*"), the chapter index\.json lists it in, got (".*")$/,
    (chapter, got) => msg(str`must be ${chapter}, the chapter index.json lists it in, got ${got}`),
  ],
  [/^(".*") is not a level of any chapter$/, (id) => msg(str`${id} is not a level of any chapter`)],
];
