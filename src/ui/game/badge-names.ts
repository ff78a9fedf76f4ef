import { msg, str } from '@lit/localize';
import type { Badge } from '../../quest/badges.ts';
import type { LevelCatalog } from '../../quest/level-index.ts';
import { playableLevels } from '../../quest/level-index.ts';
import { localize, type Locale } from '../../quest/localized-text.ts';
import { plainLevelText } from '../../quest/text-markup.ts';

/** A badge's name for the learner: the app's own words, or the level file's title for a level's own badge. */
export function badgeName(badge: Badge, catalog: LevelCatalog, locale: Locale): string {
  const level = (id: string) => playableLevels(catalog).find((candidate) => candidate.id === id);
  const levelTitle = (id: string) => {
    const found = level(id);
    return found ? plainLevelText(found.title, locale) : id;
  };
  switch (badge.kind) {
    case 'first-render':
      return msg('First render');
    case 'sandbox-saved':
      return msg('Your own scene');
    case 'chapter-done': {
      const chapter = catalog.chapters.find((candidate) => candidate.id === badge.chapter);
      return msg(str`Chapter done: ${chapter ? localize(chapter.title, locale) : badge.chapter}`);
    }
    case 'no-hints':
      return msg(str`No hints needed: ${levelTitle(badge.level)}`);
    case 'every-task':
      return msg(str`Every task: ${levelTitle(badge.level)}`);
    case 'level-badge': {
      const own = level(badge.level)?.badges.find((candidate) => candidate.id === badge.badge);
      return own ? plainLevelText(own.title, locale) : badge.badge;
    }
  }
}

/** Whether a badge was earned in (or for finishing) a level. */
export function badgeOfLevel(badge: Badge, levelId: string, chapterId: string): boolean {
  if (badge.kind === 'chapter-done') return badge.chapter === chapterId;
  return 'level' in badge && badge.level === levelId;
}
