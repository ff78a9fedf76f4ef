import { msg } from '@lit/localize';
import { translatedOrNull, type Rule } from './issue-rules.ts';
import { LEVEL_REASONS } from './level-reasons.ts';
import { RECORD_REASONS } from './record-reasons.ts';
import { SCENE_REASONS } from './scene-reasons.ts';

/**
 * Says a `path: reason` line, or a reason not coded yet (src/util/issue.ts's `worded`),
 * again in the app's language: loaded with a translation of the
 * app (issue-text.ts), not with its first screen. The most specific patterns come first:
 * the scene's generic "must be …, got …" last.
 */
const REASONS: readonly Rule[] = [...LEVEL_REASONS, ...RECORD_REASONS, ...SCENE_REASONS];

/**
 * One reason in the app's language; a reason no pattern knows is kept as it is (English
 * detail beats none). Option changes join several reasons with "; " (option-changes.ts):
 * when each is known, each is said on its own (a pattern for one would read past the "; ").
 */
export function reasonText(reason: string): string {
  const parts = reason.split('; ');
  const each = parts.map((part) => translatedOrNull(REASONS, part));
  if (parts.length > 1 && each.every((said) => said !== null)) return each.join('; ');
  return translatedOrNull(REASONS, reason) ?? each.map((said, index) => said ?? parts[index]).join('; ');
}

/** One `path: reason` line (or a bare reason); paths are field names of the file and stay as written. */
export function translateIssue(line: string): string {
  const colon = line.indexOf(': ');
  if (colon < 0) return reasonText(line);
  const path = line.slice(0, colon);
  return `${path === '(root)' ? msg('(root)') : path}: ${reasonText(line.slice(colon + 2))}`;
}
