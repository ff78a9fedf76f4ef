import { readdirSync, readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { levelSchema, type Level } from '../../src/quest/level-schema.ts';
import { LOCALES } from '../../src/quest/localized-text.ts';
import { plainLevelText } from '../../src/quest/text-markup.ts';

/**
 * A quiz must be answered by thinking, not from its form (issue 36: in 21 of 37 quizzes the
 * key was the only longest choice) or from the text above it. The order is shuffled per
 * learner (choice-order.ts); these are the checks of what a level file can give away.
 */

const levelsFolder = new URL('../../levels/', import.meta.url);
const levels: Level[] = readdirSync(levelsFolder)
  .filter((name) => name.endsWith('.level.json'))
  .map((name) => levelSchema.parse(JSON.parse(readFileSync(new URL(name, levelsFolder), 'utf8'))));

/** How much longer (or shorter) than every other choice a key may be before its length gives it away. */
const STANDS_OUT = 1.3;

/** Whether a key stands out by its length: 30 % longer than the longest other choice, or 30 % shorter than the shortest. */
function keyStandsOut(choices: readonly string[], key: number): boolean {
  const lengths = choices.map((choice) => choice.length);
  const others = lengths.filter((_, index) => index !== key);
  return lengths[key] > STANDS_OUT * Math.max(...others) || lengths[key] * STANDS_OUT < Math.min(...others);
}

/** Texts a learner reads before answering a level's quiz: the intro, and every task's title and text up to the quiz's. */
function textsAbove(level: Level, quizIndex: number, locale: (typeof LOCALES)[number]): string[] {
  const texts = [level.intro.text, ...(level.intro.more ? [level.intro.more] : [])];
  for (const [index, task] of level.tasks.entries()) {
    // Optional tasks' titles are on screen from the start; mandatory ones' texts once reached.
    texts.push(task.title);
    if (index <= quizIndex) texts.push(task.text);
  }
  return texts.map((text) => plainLevelText(text, locale).toLowerCase());
}

describe('the rule for a key that stands out', () => {
  it('flags a key much longer or shorter than the rest, and not one of a balanced set', () => {
    expect(keyStandsOut(['red', 'blue', 'a much longer and careful answer'], 2)).toBe(true);
    expect(keyStandsOut(['a long careful answer here', 'another long careful one', 'x'], 2)).toBe(true);
    expect(keyStandsOut(['smaller and sharper', 'bigger and softer', 'red like the ball'], 0)).toBe(false);
  });
});

const quizzes = levels.flatMap((level) =>
  level.tasks.flatMap((task, index) => (task.goal.kind === 'quiz' ? [{ name: `${level.id}/${task.id}`, level, index, quiz: task.goal.quiz }] : [])),
);

describe.each(LOCALES)('every quiz, in %s', (locale) => {
  it.each(quizzes)('$name: its key does not stand out by length, and no text above it holds the key', ({ level, index, quiz }) => {
    const choices = quiz.choices.map((choice) => plainLevelText(choice, locale));
    expect(keyStandsOut(choices, quiz.answer), `choices: ${choices.join(' | ')}`).toBe(false);
    const key = choices[quiz.answer].toLowerCase();
    // A short key ("12", "red") may well be written above for other reasons; a phrase may not.
    if (key.length < 16) return;
    for (const text of textsAbove(level, index, locale)) expect(text.includes(key), `"${key}" is written above the quiz`).toBe(false);
  });
});
