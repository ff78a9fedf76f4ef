import { describe, expect, it, vi } from 'vitest';
import type { ClassRecord } from '../../src/classroom/dashboard-record.ts';
import { summarizeLevels } from '../../src/classroom/dashboard-summary.ts';
import { estimatedMinutes } from '../../src/classroom/level-summary.ts';
import { keepMeasuredMinutes, MEASURED_MINUTES_KEY, measuredMinutes, readMeasuredMinutes } from '../../src/classroom/measured-minutes.ts';
import type { Assignment } from '../../src/classroom/assignment.ts';
import { playableLevels } from '../../src/quest/level-index.ts';
import { MemoryStorage } from '../../src/quest/saved-backups.ts';
import { levelMinutes, totalMinutesText } from '../../src/ui/classroom/teacher-minutes.ts';
import { catalogOf, levelWithId } from '../support/quest-fixtures.ts';

const MINUTE = 60_000;

/** A learner who visited levels, each for `minutes` of active time, passed or not. */
const learner = (name: string, visits: [level: string, minutes: number, passed: boolean][]): ClassRecord => ({
  file: `${name}.json`,
  participant: name,
  learnerId: name,
  attemptId: `attempt-${name}`,
  installId: '',
  assignment: 'Lesson',
  assignmentId: 'abc',
  classCode: '',
  appVersion: '',
  utcOffsetMin: '',
  attempts: [],
  visits: visits.map(([level, minutes, passed]) => ({ level, durationMs: minutes * MINUTE + 5000, activeMs: minutes * MINUTE, passed })),
  survey: null,
});

describe("a class's typical minutes per level", () => {
  const records = [
    learner('p1', [
      ['01-a', 4, true],
      ['02-b', 3, true],
    ]),
    learner('p2', [
      ['01-a', 11, true],
      ['02-b', 9, true],
    ]),
    learner('p3', [
      ['01-a', 6, true],
      ['02-b', 2.5, true],
    ]),
    learner('p4', [['01-a', 8, true]]),
    // Did not pass: not one of the times the median is of.
    learner('p5', [
      ['01-a', 30, false],
      ['03-c', 12, false],
    ]),
  ];

  it('is the median active time of the learners who passed, with how many they were', () => {
    // By hand: 01-a passed in 4, 11, 6, 8 → sorted 4, 6, 8, 11 → (6 + 8) / 2 = 7.
    // 02-b passed in 3, 9, 2.5 → sorted 2.5, 3, 9 → 3. Nobody passed 03-c: no figure.
    expect(measuredMinutes(summarizeLevels(records))).toEqual({ '01-a': { minutes: 7, learners: 4 }, '02-b': { minutes: 3, learners: 3 } });
  });

  it('is kept in the browser over the earlier figures of the same levels only, and read back', () => {
    const storage = new MemoryStorage();
    expect(readMeasuredMinutes(storage)).toEqual({});
    expect(keepMeasuredMinutes(storage, { '01-a': { minutes: 7, learners: 4 }, '02-b': { minutes: 3, learners: 3 } })).toBe(true);
    expect(keepMeasuredMinutes(storage, { '02-b': { minutes: 5.5, learners: 20 } })).toBe(true);
    expect(readMeasuredMinutes(storage)).toEqual({ '01-a': { minutes: 7, learners: 4 }, '02-b': { minutes: 5.5, learners: 20 } });
    // Only aggregates: no code, file or learner's name is stored.
    expect(storage.getItem(MEASURED_MINUTES_KEY)).not.toMatch(/p1|\.json|Lesson/);
  });

  it('reads as nothing when what was kept is damaged, and reports a refused write', () => {
    const storage = new MemoryStorage();
    storage.setItem(MEASURED_MINUTES_KEY, '{"version":1,"levels":{"01-a":{"minutes":-3,"learners":2}}}');
    expect(readMeasuredMinutes(storage)).toEqual({});
    storage.setItem(MEASURED_MINUTES_KEY, 'not json');
    expect(readMeasuredMinutes(storage)).toEqual({});
    const full = Object.assign(new MemoryStorage(), {
      setItem: () => {
        throw new DOMException('full', 'QuotaExceededError');
      },
    });
    expect(keepMeasuredMinutes(full, { '01-a': { minutes: 7, learners: 4 } })).toBe(false);
  });
});

describe("the teacher page's minutes", () => {
  const [first, second] = playableLevels(catalogOf([{ id: 'test', levels: [levelWithId('first'), levelWithId('second')] }]));
  const required = first.tasks.map((task) => task.id);

  it("shows the class's median rounded to a half minute, else the estimate", () => {
    expect(levelMinutes(first, required, { minutes: 6.8, learners: 12 })).toBe(7);
    expect(levelMinutes(first, required, { minutes: 6.7, learners: 12 })).toBe(6.5);
    expect(levelMinutes(first, required, { minutes: 0.1, learners: 1 })).toBe(0.5);
    expect(levelMinutes(first, required, undefined)).toBe(estimatedMinutes(first, required));
  });

  it('adds the measured and the estimated levels, and says which it used', () => {
    // The page writes numbers in the browser's variant of its language (format-locale.ts).
    vi.stubGlobal('navigator', { languages: ['en-GB'] });
    const a: Assignment = {
      version: 1,
      title: 'Lesson',
      levels: ['first', 'second'],
      requiredTasks: { first: required, second: [] },
      otherLevels: 'hidden',
      locale: 'en',
      askParticipantCode: false,
      survey: null,
    };
    const estimate = estimatedMinutes(second, []);
    expect(totalMinutesText(a, [first, second], { first: { minutes: 10, learners: 3 } })).toMatch(
      new RegExp(`^In all about ${10 + estimate} minutes: the median`),
    );
    expect(totalMinutesText(a, [first, second], {})).toContain('(an estimate from the kinds of task, not measured)');
    vi.unstubAllGlobals();
  });
});
