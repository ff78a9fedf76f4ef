import { msg, str } from '@lit/localize';
import { value, type Rule } from './issue-rules.ts';

/**
 * The reasons saved progress and an assignment link are refused for, beyond the scene
 * schema's (src/quest/progress-store.ts, src/quest/event-log.ts,
 * src/classroom/assignment-schema.ts), said again in the app's language.
 */
export const RECORD_REASONS: readonly Rule[] = [
  [/^must be (".*") in a progress file, got (.+)$/, (kind, got) => msg(str`must be ${kind} in a progress file, got ${value(got)}`)],
  [/^this app reads progress version (\d+), got (.+)$/, (version, got) => msg(str`this app reads progress version ${version}, got ${value(got)}`)],
  [/^must not be earlier than the event before it$/, () => msg('must not be earlier than the event before it')],
  [/^(".*") is listed more than once$/, (id) => msg(str`${id} is listed more than once`)],
  [/^(".*") is not one of the assignment's levels$/, (id) => msg(str`${id} is not one of the assignment's levels`)],
  // zod's own wording for a text that breaks its pattern (an event's id in the log).
  [/^Invalid string: must match pattern (.+)$/, (pattern) => msg(str`Invalid string: must match pattern ${pattern}`)],
  [/^must be a web address that starts with http:\/\/ or https:\/\/$/, () => msg('must be a web address that starts with http:// or https://')],
  [/^a class code has 1 to 32 letters, digits, - or _$/, () => msg('a class code has 1 to 32 letters, digits, - or _')],
];
