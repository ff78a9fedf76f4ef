import type { Level } from '../quest/level-schema.ts';
import type { Assignment } from './assignment.ts';
import { ownSurveyChoice } from './survey-for-levels.ts';
import { surveyById } from './surveys.ts';

/**
 * The assignment as its link carries it: a level whose required tasks are the level's own
 * mandatory ones is left out of `requiredTasks`, since the game requires those by default
 * (level-gate.ts requiredTaskIds), and the survey's questions only where the teacher's
 * choice differs from the default (survey-for-levels.ts). Fewer characters make a QR code
 * with fewer, larger squares, which a phone at the back of the classroom reads.
 */
export function compactAssignment(assignment: Assignment, levels: readonly Level[]): Assignment {
  const requiredTasks = Object.fromEntries(
    Object.entries(assignment.requiredTasks).filter(([id, tasks]) => {
      const level = levels.find((candidate) => candidate.id === id);
      const mandatory = level?.tasks.filter((task) => task.mandatory).map((task) => task.id);
      return !mandatory || mandatory.length !== tasks.length || mandatory.some((task) => !tasks.includes(task));
    }),
  );
  const { surveyQuestions, ...rest } = assignment;
  const choice = assignment.survey === null ? undefined : ownSurveyChoice(surveyById(assignment.survey), assignment.levels, surveyQuestions);
  return choice ? { ...rest, requiredTasks, surveyQuestions: choice } : { ...rest, requiredTasks };
}
