import { msg, str } from '@lit/localize';
import type { AssignmentLinkResult } from '../../classroom/assignment-link.ts';
import { issueText } from '../../i18n/issue-text.ts';
import { shortList } from '../../i18n/short-list.ts';

/**
 * Why an assignment link did not open, for the notice over the page: the first few reasons
 * and how many more (a link naming 100 unknown levels must not fill the screen).
 */
export function linkProblemText(result: Extract<AssignmentLinkResult, { ok: false }>): string {
  const reasons = shortList(result.reasons.map(issueText));
  switch (result.kind) {
    case 'damaged':
      return msg(str`This assignment link is damaged (${reasons}). You are playing freely.`);
    case 'other-version':
      return msg(str`This assignment link was made for another version of the game (${reasons}). You are playing freely.`);
    case 'unknown-levels':
      return msg(str`This assignment link names levels or tasks this version of the game does not have: ${reasons}. You are playing freely.`);
  }
}
