/**
 * Whether a multiple-choice key gives itself away by its length (issue 36: in 21 of 37 level
 * quizzes the key was the only longest choice). The rule of the level quizzes
 * (tests/quest/quiz-form.test.ts), shared here for every bank of choices.
 */

/** How much longer (or shorter) than every other choice a key may be before its length gives it away. */
export const STANDS_OUT = 1.3;

/** The key is 30 % longer than the longest other choice, or 30 % shorter than the shortest. */
export function keyStandsOut(choices: readonly string[], key: number): boolean {
  const lengths = choices.map((choice) => choice.length);
  const others = lengths.filter((_, index) => index !== key);
  return lengths[key] > STANDS_OUT * Math.max(...others) || lengths[key] * STANDS_OUT < Math.min(...others);
}

/** The key is longer than every other choice: the choice a guesser picks first. */
export function keyIsLongest(choices: readonly string[], key: number): boolean {
  return choices.every((choice, index) => index === key || choice.length < choices[key].length);
}
