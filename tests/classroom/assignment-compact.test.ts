import { describe, expect, it } from 'vitest';
import type { Assignment } from '../../src/classroom/assignment.ts';
import { compactAssignment } from '../../src/classroom/assignment-compact.ts';
import { requiredTaskIds } from '../../src/quest/level-gate.ts';
import { playableLevels } from '../../src/quest/level-index.ts';
import { catalogOf, levelWithId } from '../support/quest-fixtures.ts';

const levels = playableLevels(catalogOf([{ id: 'test', levels: [levelWithId('first'), levelWithId('second'), levelWithId('third')] }]));
const assignment: Assignment = {
  version: 1,
  title: 'Lesson',
  levels: ['first', 'second', 'third'],
  // first: the level's own mandatory tasks (in another order); second: one more; third: none at all.
  requiredTasks: { first: ['supersample', 'orbit', 'predict'], second: ['orbit', 'predict', 'supersample', 'zoom'], third: [] },
  otherLevels: 'hidden',
  locale: 'en',
  askParticipantCode: false,
  survey: null,
};

describe('the compact assignment of a link', () => {
  const compact = compactAssignment(assignment, levels);

  it('leaves out the levels that require their own mandatory tasks', () => {
    expect(compact.requiredTasks).toEqual({ second: ['orbit', 'predict', 'supersample', 'zoom'], third: [] });
  });

  it("carries the teacher's survey questions only where they differ from the default, and none without a survey", () => {
    const withSurvey: Assignment = { ...assignment, survey: 'default', surveyQuestions: { 'learned-ray-tracing': true, age: false } };
    // learned-ray-tracing is asked anyway (it names no levels): only "age off" is the teacher's own.
    expect(compactAssignment(withSurvey, levels).surveyQuestions).toEqual({ age: false });
    expect('surveyQuestions' in compactAssignment({ ...withSurvey, surveyQuestions: { 'learned-ray-tracing': true } }, levels)).toBe(false);
    expect('surveyQuestions' in compactAssignment({ ...withSurvey, survey: null }, levels)).toBe(false);
  });

  it('requires the same tasks in the game', () => {
    for (const level of levels) expect(requiredTaskIds(level, compact.requiredTasks)).toEqual(requiredTaskIds(level, assignment.requiredTasks));
  });
});
