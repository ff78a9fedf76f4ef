import { describe, expect, it } from 'vitest';
import type { Assignment } from '../../src/classroom/assignment.ts';
import { compactAssignment } from '../../src/classroom/assignment-compact.ts';
import { expandAssignment } from '../../src/classroom/assignment-expand.ts';
import { mandatoryTasks } from '../../src/classroom/assignment-preset.ts';
import { playableLevels } from '../../src/quest/level-index.ts';
import { assignmentHashOfTeacherLink, teacherLinkHash } from '../../src/classroom/teacher-link.ts';
import { catalogOf, levelWithId } from '../support/quest-fixtures.ts';

const levels = playableLevels(catalogOf([{ id: 'test', levels: [levelWithId('first'), levelWithId('second')] }]));

describe('an assignment link opened on the teacher page', () => {
  it('ticks the mandatory tasks of the levels the link left out, and keeps the others as given', () => {
    const [first, second] = levels;
    const made: Assignment = {
      version: 1,
      title: 'Lesson',
      levels: ['first', 'second'],
      requiredTasks: { first: mandatoryTasks(first), second: [] },
      otherLevels: 'hidden',
      locale: 'nl',
      askParticipantCode: true,
      survey: null,
      classCode: '5H2',
    };
    const link = compactAssignment(made, levels);
    expect(link.requiredTasks).toEqual({ second: [] });
    expect(expandAssignment(link, levels)).toEqual(made);
    expect(mandatoryTasks(second).length).toBeGreaterThan(0);
  });
});

describe("the teacher page's address for an assignment", () => {
  it('carries the students’ link and gives it back', () => {
    const students = '#/a/1.eJwrSS0uUTAEAAiOAhI';
    expect(teacherLinkHash(students)).toBe('#/teacher/a/1.eJwrSS0uUTAEAAiOAhI');
    expect(assignmentHashOfTeacherLink(teacherLinkHash(students))).toBe(students);
    expect(assignmentHashOfTeacherLink('#/teacher')).toBeNull();
  });
});
