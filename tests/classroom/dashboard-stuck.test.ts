import { describe, expect, it } from 'vitest';
import { stickingPoints } from '../../src/classroom/dashboard-stuck.ts';
import type { TaskSummary } from '../../src/classroom/dashboard-summary.ts';

const task = (id: string, needingHelp: number, learners = 20, mandatory = true): TaskSummary => ({
  level: 'l',
  task: id,
  mandatory,
  kind: 'do',
  learners,
  done: learners,
  shown: 0,
  skipped: 0,
  times: [],
  stats: null,
  hintsText: needingHelp,
  hintsGuidance: 0,
  learnersWithHints: needingHelp,
  learnersNeedingHelp: needingHelp,
});

describe('sticking points', () => {
  it('does not flag a level where most tasks see some help (6 of 7 above 40 %)', () => {
    const typical = [9, 10, 9, 11, 10, 9, 3].map((help, index) => task(`t${index}`, help));
    expect(stickingPoints(typical)).toEqual(new Set());
  });

  it('flags the task far above the rest of its level', () => {
    const tasks = [2, 3, 2, 16, 4, 3, 2].map((help, index) => task(`t${index}`, help));
    expect(stickingPoints(tasks)).toEqual(new Set(['t3']));
  });

  it('needs a high share as well: twice a low median is not stuck', () => {
    expect(stickingPoints([1, 1, 2, 5].map((help, index) => task(`t${index}`, help)))).toEqual(new Set());
  });

  it('leaves out optional tasks and tasks with fewer than 3 learners', () => {
    expect(stickingPoints([task('a', 0), task('b', 0), task('optional', 18, 20, false), task('few', 2, 2)])).toEqual(new Set());
  });
});
