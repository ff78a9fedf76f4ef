import type { ClassRecord } from './dashboard-record.ts';
import type { ChoiceQuestion } from './quiz-options.ts';

/**
 * Quiz results per question, for the dashboard: how many learners answered, the share who
 * chose the right option, and how often each option was chosen (which wrong answer a class
 * gives most is what a teacher discusses next lesson).
 *
 * Each learner counts once per question, with their first answer: a quiz is a prediction
 * made before the result is shown, and a learner who plays the level again has seen it.
 * Only choice questions count (`quiz_choice`); a file from before choices were exported
 * has none, so its learners are not in n.
 */

export interface OptionCount {
  /** The option's position in the level file (its id is the letter, quiz-options.ts). */
  position: number;
  text: string;
  right: boolean;
  /** Learners whose first answer was this option. */
  learners: number;
}

export interface QuizSummary {
  level: string;
  task: string;
  question: string;
  pictures: boolean;
  /** Learners who answered (n). */
  learners: number;
  /** Learners whose first answer was right. */
  right: number;
  /** Every option, in level-file order, chosen or not. */
  options: OptionCount[];
}

/** The summary of every question of `questions` that at least one of `records` answered, in the questions' order. */
export function summarizeQuizzes(records: readonly ClassRecord[], questions: readonly ChoiceQuestion[]): QuizSummary[] {
  return questions.flatMap((question) => {
    const firstChoices = records.flatMap((record) => {
      const first = record.attempts.find((attempt) => attempt.level === question.level && attempt.task === question.task && attempt.quizChoice !== null);
      return first?.quizChoice == null ? [] : [first.quizChoice];
    });
    if (firstChoices.length === 0) return [];
    const options = question.options.map((text, position) => ({
      position,
      text,
      right: position === question.answer,
      learners: firstChoices.filter((choice) => choice === position).length,
    }));
    return [
      {
        level: question.level,
        task: question.task,
        question: question.question,
        pictures: question.pictures,
        learners: firstChoices.length,
        right: firstChoices.filter((choice) => choice === question.answer).length,
        options,
      },
    ];
  });
}
