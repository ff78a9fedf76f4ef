import { msg, str } from '@lit/localize';

/**
 * The `path: reason` lines that say why a scene file, a level, a link or saved progress
 * cannot be used, in the app's language. The schemas and the JSON reader are pure (no lit;
 * `rt validate` prints them as they are) and word their reasons in English
 * (src/scene/scene-issues.ts, src/scene/scene-schema-parts.ts, src/scene/scene-rules.ts,
 * src/util/json-error.ts); here the learner-facing app reads each reason by its English
 * pattern and says it again through msg(). A reason no pattern knows is kept as it is:
 * English detail beats none. Paths are field names of the file and stay as written.
 */

/** A pattern and what to say for a match; null when, after all, it is not this rule's to say. */
type Rule = readonly [RegExp, (...parts: string[]) => string | null];

/** The values in "got …" (describeValue in scene-issues.ts); JSON literals and quoted text stay. */
const VALUES: readonly Rule[] = [
  [/^nothing$/, () => msg('nothing')],
  [/^a list of 1 item$/, () => msg('a list of 1 item')],
  [/^a list of (\d+) items$/, (count) => msg(str`a list of ${count} items`)],
  [/^an object$/, () => msg('an object')],
];

/** What a value must be (EXPECTED in scene-issues.ts, the list items of scene-schema-parts.ts). */
const KINDS: readonly Rule[] = [
  [/^a number$/, () => msg('a number')],
  [/^a string$/, () => msg('a text')],
  [/^true or false$/, () => msg('true or false')],
  [/^an object$/, () => msg('an object')],
  [/^a list$/, () => msg('a list')],
  [/^a whole number$/, () => msg('a whole number')],
  [/^one of (.+)$/, (values) => msg(str`one of ${values}`)],
  [/^a list of (\d+) numbers$/, (count) => msg(str`a list of ${count} numbers`)],
  [/^a list of (\d+) whole numbers$/, (count) => msg(str`a list of ${count} whole numbers`)],
  [/^a list of (\d+) positive numbers$/, (count) => msg(str`a list of ${count} positive numbers`)],
  [/^a list of (\d+) numbers between 0 and 1$/, (count) => msg(str`a list of ${count} numbers between 0 and 1`)],
  // One allowed value (oneOf in scene-issues.ts): a quoted text or a JSON literal, the same in every language.
  [/^(".*"|-?\d[\d.e+-]*|true|false|null)$/, (literal) => literal],
];

/** What JSON.parse's reader expected or found (json-error.ts). */
const JSON_PARTS: readonly Rule[] = [
  [/^a value$/, () => msg('a value')],
  [/^a field name in double quotes$/, () => msg('a field name in double quotes')],
  [/^"(.)" or "(.)"$/, (one, other) => msg(str`"${one}" or "${other}"`)],
  [/^a closing '"' \(write a line break inside a string as \\n\)$/, () => msg('a closing \'"\' (write a line break inside a string as \\n)')],
  [/^an escape such as .+$/, () => msg('an escape such as \\n, \\" or \\u00e9')],
  [/^a closing '"'$/, () => msg('a closing \'"\'')],
  [/^the end of the text$/, () => msg('the end of the text')],
  [/^less deeply nested lists and objects$/, () => msg('less deeply nested lists and objects')],
];

/** The reasons themselves, the most specific first. */
const REASONS: readonly Rule[] = [
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
  [/^must be lower-case letters and digits joined by "-", like "([^"]*)", got (.+)$/, (example, got) => msg(str`must be lower-case letters and digits joined by "-", like "${example}", got ${value(got)}`)],
  [/^must have (\d+) to (\d+) mandatory tasks, got (\d+)$/, (fewest, most, count) => msg(str`must have ${fewest} to ${most} mandatory tasks, got ${count}`)],
  [/^must be the position of a choice, 0 to (\d+)$/, (last) => msg(str`must be the position of a choice, 0 to ${last}`)],
  // Any other "must be …, got …" only when what it must be is known: half a sentence in each language reads worse than English.
  [/^must be (.+), got (.+)$/, (kind, got) => {
    const must = translatedOrNull(KINDS, kind);
    return must === null ? null : msg(str`must be ${must}, got ${value(got)}`);
  }],
  [/^unknown field (".*")$/, (name) => msg(str`unknown field ${name}`)],
  [/^unknown fields (".*")$/, (names) => msg(str`unknown fields ${names}`)],
  [/^(".*") is used twice$/, (id) => msg(str`${id} is used twice`)],
  [/^(".*") is used more than once$/, (id) => msg(str`${id} is used more than once`)],
  [/^(".*") is used (\d+) times$/, (id, count) => msg(str`${id} is used ${count} times`)],
  [/^makes (.+) = (\d+) primary rays per pixel, more than (\d+)$/, (sum, rays, most) => msg(str`makes ${sum} = ${rays} primary rays per pixel, more than ${most}`)],
  [
    /^not valid JSON at line (\d+), column (\d+): expected (.+), found (.+)$/,
    (line, column, expected, found) => msg(str`not valid JSON at line ${line}, column ${column}: expected ${translated(JSON_PARTS, expected)}, found ${translated(JSON_PARTS, found)}`),
  ],
];

/** What the first rule that matches all of `text` says, or null when none does. */
function translatedOrNull(rules: readonly Rule[], text: string): string | null {
  for (const [pattern, say] of rules) {
    const match = pattern.exec(text);
    const said = match ? say(...match.slice(1)) : null;
    if (said !== null) return said;
  }
  return null;
}

/** `text` said by the first rule that knows it; `text` itself when none does. */
function translated(rules: readonly Rule[], text: string): string {
  return translatedOrNull(rules, text) ?? text;
}

const value = (text: string) => translated(VALUES, text);

/** One `path: reason` line (or a bare reason) in the app's language. */
export function issueText(line: string): string {
  const colon = line.indexOf(': ');
  if (colon < 0) return translated(REASONS, line);
  const path = line.slice(0, colon);
  return `${path === '(root)' ? msg('(root)') : path}: ${translated(REASONS, line.slice(colon + 2))}`;
}

/** Every line of a multi-line reason (a store's refusal may hold several) in the app's language. */
export function issueLines(text: string): string {
  return text.split('\n').map(issueText).join('\n');
}
