import { describe, expect, it } from 'vitest';
import { shortList } from '../../../src/i18n/short-list.ts';
import { linkProblemText } from '../../../src/ui/shell/link-problem-text.ts';
import { wordedIssue } from '../../../src/util/issue.ts';

describe('the notice of an assignment link that did not open', () => {
  it('names the first few unknown levels and how many more, not all 100', () => {
    const reasons = Array.from({ length: 100 }, (_, index) => `level-with-a-long-name-number-${index}`);
    const text = linkProblemText({ ok: false, kind: 'unknown-levels', reasons: reasons.map((id) => wordedIssue(null, id)) });
    expect(text).toBe(
      `This assignment link names levels or tasks this version of the game does not have: ${reasons.slice(0, 5).join('; ')} and 95 more. You are playing freely.`,
    );
    expect(text.length).toBeLessThan(400);
  });

  it('lists them all when there are few', () => {
    expect(linkProblemText({ ok: false, kind: 'unknown-levels', reasons: [wordedIssue(null, 'a'), wordedIssue(null, 'b')] })).toBe(
      'This assignment link names levels or tasks this version of the game does not have: a; b. You are playing freely.',
    );
    expect(shortList(['a', 'b', 'c', 'd', 'e', 'f'])).toBe('a; b; c; d; e; f');
    expect(shortList(['a', 'b', 'c', 'd', 'e', 'f', 'g'])).toBe('a; b; c; d; e and 2 more');
  });
});
