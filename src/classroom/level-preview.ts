import type { Level } from '../quest/level-schema.ts';
import type { Locale } from '../quest/localized-text.ts';
import { plainLevelText } from '../quest/text-markup.ts';
import type { Assignment } from './assignment.ts';
import { mandatoryTasks } from './assignment-preset.ts';

/**
 * A teacher's look at one level (`#/preview/<level id>`), without playing the ones before it:
 * the level played as an assignment of that level alone, so the game's own rules open it
 * (an assignment's first level is never locked) and nothing else is shown. The lab plays it
 * with storage that lives as long as the page (quest-controller.ts), so a preview saves no
 * progress, no times and no record next to a real assignment's or free play's.
 */

/** The address fragment of a level's preview, without the level id. */
export const LEVEL_PREVIEW = '#/preview/';

export function levelPreviewHash(levelId: string): string {
  return `${LEVEL_PREVIEW}${encodeURIComponent(levelId)}`;
}

/** The level id a preview address names, or null when it is not one. */
export function previewedLevelId(hash: string): string | null {
  if (!hash.startsWith(LEVEL_PREVIEW)) return null;
  try {
    return decodeURIComponent(hash.slice(LEVEL_PREVIEW.length)) || null;
  } catch {
    return null;
  }
}

/** The one-level assignment a preview plays, in the page's language. */
export function previewAssignment(level: Level, locale: Locale): Assignment {
  return {
    version: 1,
    title: plainLevelText(level.title, locale),
    levels: [level.id],
    requiredTasks: { [level.id]: mandatoryTasks(level) },
    otherLevels: 'hidden',
    locale,
    askParticipantCode: false,
    survey: null,
  };
}
