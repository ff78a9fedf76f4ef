import type { Level } from '../quest/level-schema.ts';
import type { Locale } from '../quest/localized-text.ts';
import { plainLevelText } from '../quest/text-markup.ts';

/**
 * The options of a level's choice questions as exports and the dashboard name them. Level
 * files list a quiz's choices without ids, and the learner sees them shuffled
 * (choice-order.ts), so an option is named by its position in the level file as a letter:
 * a, b, c… (`quiz_choice`). The letter stays the option's as long as the level file keeps
 * its choices in order; the codebook lists each letter with its text, so a researcher can
 * read a file without the level files.
 */

/** The option id of the choice at `position` (0 → "a"). */
export function optionId(position: number): string {
  return String.fromCharCode(0x61 + position);
}

/** The position of an option id ("a" → 0), or null when the cell is not one. */
export function optionPosition(id: string): number | null {
  return /^[a-z]$/.test(id) ? id.charCodeAt(0) - 0x61 : null;
}

/** One choice question: a word quiz (its options' texts) or a picture quiz (no texts, the options are renders). */
export interface ChoiceQuestion {
  level: string;
  task: string;
  question: string;
  /** The option texts in file order; a picture's option is named "picture a", "picture b"… in the codebook. */
  options: string[];
  pictures: boolean;
  /** The right option's position. */
  answer: number;
}

/** Every choice question of `levels`, in level and task order, with its texts in `locale`. */
export function choiceQuestions(levels: readonly Level[], locale: Locale): ChoiceQuestion[] {
  return levels.flatMap((level) =>
    level.tasks.flatMap((task): ChoiceQuestion[] => {
      const { goal } = task;
      if (goal.kind === 'quiz') {
        const { question, choices, answer } = goal.quiz;
        return [
          {
            level: level.id,
            task: task.id,
            question: plainLevelText(question, locale),
            options: choices.map((text) => plainLevelText(text, locale)),
            pictures: false,
            answer,
          },
        ];
      }
      if (goal.kind === 'picture') {
        const { question, choices, answer } = goal.picture;
        return [{ level: level.id, task: task.id, question: plainLevelText(question, locale), options: choices.map(() => ''), pictures: true, answer }];
      }
      return [];
    }),
  );
}

/** The text of a chosen option, looked up by level, task and position ('' for a picture or an unknown question). */
export type OptionText = (level: string, task: string, position: number) => string;

export const NO_OPTION_TEXTS: OptionText = () => '';

export function optionTexts(questions: readonly ChoiceQuestion[]): OptionText {
  const byTask = new Map(questions.map((question) => [`${question.level}/${question.task}`, question.options]));
  return (level, task, position) => byTask.get(`${level}/${task}`)?.[position] ?? '';
}
