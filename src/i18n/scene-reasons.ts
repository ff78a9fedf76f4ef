import { msg, str } from '@lit/localize';
import { KINDS, translated, translatedOrNull, value, type Rule } from './issue-rules.ts';

/**
 * The reasons of the scene schema and the JSON reader, pure and English
 * (src/scene/scene-issues.ts, src/scene/scene-schema-parts.ts, src/scene/scene-rules.ts,
 * src/util/json-error.ts), said again in the app's language. Level files, progress and
 * assignments use the same schema parts, so their generic reasons are these too.
 */

/** What JSON.parse's reader expected or found (json-error.ts). */
const JSON_PARTS: readonly Rule[] = [
  [/^a value$/, () => msg('a value')],
  [/^a field name in double quotes$/, () => msg('a field name in double quotes')],
  [/^"(.)" or "(.)"$/, (one, other) => msg(str`"${one}" or "${other}"`)],
  [/^a closing '"' \(write a line break inside a string as \\n\)$/, () => msg("a closing '\"' (write a line break inside a string as \\n)")],
  [/^an escape such as .+$/, () => msg('an escape such as \\n, \\" or \\u00e9')],
  [/^a closing '"'$/, () => msg("a closing '\"'")],
  [/^the end of the text$/, () => msg('the end of the text')],
  [/^less deeply nested lists and objects$/, () => msg('less deeply nested lists and objects')],
];

/** The reasons themselves, the most specific first. */
export const SCENE_REASONS: readonly Rule[] = [
  [/^is required$/, () => msg('is required')],
  [/^is required when shape is "mesh" \(one of (.+)\)$/, (meshes) => msg(str`is required when shape is "mesh" (one of ${meshes})`)],
  [/^is only allowed when shape is "mesh"$/, () => msg('is only allowed when shape is "mesh"')],
  [/^must differ from camera\.position$/, () => msg('must differ from camera.position')],
  [/^must not be empty$/, () => msg('must not be empty')],
  [/^must be at most (\d+) characters long$/, (most) => msg(str`must be at most ${most} characters long`)],
  [/^must have at least (\d+) items, got (.+)$/, (least, got) => msg(str`must have at least ${least} items, got ${value(got)}`)],
  [/^must have at most (\d+) items, got (.+)$/, (most, got) => msg(str`must have at most ${most} items, got ${value(got)}`)],
  [/^must be at least (\S+), got (.+)$/, (least, got) => msg(str`must be at least ${least}, got ${value(got)}`)],
  [/^must be at most (\S+), got (.+)$/, (most, got) => msg(str`must be at most ${most}, got ${value(got)}`)],
  [/^must be between (\S+) and (\S+), got (.+)$/, (lowest, highest, got) => msg(str`must be between ${lowest} and ${highest}, got ${value(got)}`)],
  [/^must be a whole number from 0 to (\d+), got (.+)$/, (most, got) => msg(str`must be a whole number from 0 to ${most}, got ${value(got)}`)],
  [/^must be inside the (\d+)×(\d+) screen, got (.+)$/, (columns, rows, got) => msg(str`must be inside the ${columns}×${rows} screen, got ${got}`)],
  [
    /^must be a text, or \{ "en": …, "nl": … \} with a text per language \(en is required; each at most (\d+) characters\)$/,
    (most) => msg(str`must be a text, or { "en": …, "nl": … } with a text per language (en is required; each at most ${most} characters)`),
  ],
  [
    /^must be lower-case letters and digits joined by "-", like "([^"]*)", got (.+)$/,
    (example, got) => msg(str`must be lower-case letters and digits joined by "-", like "${example}", got ${value(got)}`),
  ],
  [/^must have (\d+) to (\d+) mandatory tasks, got (\d+)$/, (fewest, most, count) => msg(str`must have ${fewest} to ${most} mandatory tasks, got ${count}`)],
  [/^must be the position of a choice, 0 to (\d+)$/, (last) => msg(str`must be the position of a choice, 0 to ${last}`)],
  // Any other "must be …, got …" only when what it must be is known: half a sentence in each language reads worse than English.
  [
    /^must be (.+), got (.+)$/,
    (kind, got) => {
      const must = translatedOrNull(KINDS, kind);
      return must === null ? null : msg(str`must be ${must}, got ${value(got)}`);
    },
  ],
  // Field names are JSON strings (scene-issues.ts): a looser pattern would take in English words after them.
  [/^unknown field ("(?:[^"\\]|\\.)*")$/, (name) => msg(str`unknown field ${name}`)],
  [/^unknown fields ("(?:[^"\\]|\\.)*"(?:, "(?:[^"\\]|\\.)*")*)$/, (names) => msg(str`unknown fields ${names}`)],
  [/^(".*") is used twice$/, (id) => msg(str`${id} is used twice`)],
  [/^(".*") is used more than once$/, (id) => msg(str`${id} is used more than once`)],
  [/^(".*") is used (\d+) times$/, (id, count) => msg(str`${id} is used ${count} times`)],
  [
    /^makes (.+) = (\d+) primary rays per pixel, more than (\d+)$/,
    (sum, rays, most) => msg(str`makes ${sum} = ${rays} primary rays per pixel, more than ${most}`),
  ],
  [
    /^not valid JSON at line (\d+), column (\d+): expected (.+), found (.+)$/,
    (line, column, expected, found) =>
      msg(str`not valid JSON at line ${line}, column ${column}: expected ${translated(JSON_PARTS, expected)}, found ${translated(JSON_PARTS, found)}`),
  ],
];
