import { msg, str } from '@lit/localize';
import { twoStarLimit, type ChallengePar } from '../../quest/challenge-par.ts';
import type { Locale } from '../../quest/localized-text.ts';

/**
 * The star rule a challenge shows before the start (spec/challenges.md §2), naming what its
 * par counts: "Stars: ★★★ within 3 renders, ★★ within 4, ★ for any match."
 */
export function starRuleText(par: ChallengePar, locale: Locale): string {
  const two = twoStarLimit(par);
  switch (par.kind) {
    case 'renders':
      return msg(str`Stars: ★★★ within ${par.limit} renders, ★★ within ${two}, ★ for any match.`);
    case 'changes':
      return msg(str`Stars: ★★★ within ${par.limit} changes, ★★ within ${two}, ★ for any match.`);
    case 'rays':
      return msg(str`Stars: ★★★ within ${rayCount(par.limit, locale)} rays in all your renders, ★★ within ${rayCount(two, locale)}, ★ for any match.`);
    default: {
      const never: never = par.kind;
      return never;
    }
  }
}

/** "2 million", "2 miljoen", "77 thousand": a count of rays a pupil reads at a glance. */
export function rayCount(rays: number, locale: Locale): string {
  return new Intl.NumberFormat(locale, { notation: 'compact', compactDisplay: 'long', maximumSignificantDigits: 3 }).format(rays);
}
