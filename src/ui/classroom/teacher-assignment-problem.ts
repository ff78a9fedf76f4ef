import { msg } from '@lit/localize';
import type { Assignment } from '../../classroom/assignment.ts';
import { assignmentSchema, CLASS_CODE } from '../../classroom/assignment-schema.ts';
import { asksNoSurveyQuestion } from './teacher-survey-questions.ts';

/** The problem that keeps the teacher page's assignment from being a link, in the teacher's words, or null. */
export function assignmentProblem(a: Assignment): string | null {
  if (a.title.trim() === '') return msg('Give the assignment a title.');
  if (a.levels.length === 0) return msg('Add at least one level.');
  if (asksNoSurveyQuestion(a)) return msg('Tick at least one survey question, or choose no closing survey.');
  const { classCode, xapiHomePage } = a;
  if (classCode !== undefined && !CLASS_CODE.test(classCode)) return msg('A class code has up to 32 letters, digits, - or _ (no spaces).');
  if (xapiHomePage !== undefined && !assignmentSchema.shape.xapiHomePage.safeParse(xapiHomePage).success) {
    return msg("The school's address for xAPI must be a web address starting with https:// or http://.");
  }
  return null;
}
