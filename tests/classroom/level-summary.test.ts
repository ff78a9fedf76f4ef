import { existsSync, readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { mandatoryTasks } from '../../src/classroom/assignment-preset.ts';
import { estimatedMinutes, INTRO_MINUTES, MINUTES_PER_TASK, taskKindCounts } from '../../src/classroom/level-summary.ts';
import { loadLevels, playableLevels } from '../../src/quest/level-index.ts';

const levelsFolder = new URL('../../levels/', import.meta.url);
const readLevelFile = (name: string) => (existsSync(new URL(name, levelsFolder)) ? readFileSync(new URL(name, levelsFolder), 'utf8') : undefined);
const levels = playableLevels(loadLevels(readFileSync(new URL('index.json', levelsFolder), 'utf8'), readLevelFile));
const level = (id: string) => levels.find((candidate) => candidate.id === id) ?? expect.unreachable(id);

describe('what each level asks, for the teacher page', () => {
  it('counts the task kinds of a level, every task once', () => {
    for (const each of levels) {
      const counts = taskKindCounts(each);
      expect(counts.reduce((sum, { count }) => sum + count, 0)).toBe(each.tasks.length);
    }
    // Level 2 (rays from the camera): an info step, two choice questions, a number to estimate,
    // six things to do in the lab and a function to write.
    expect(taskKindCounts(level('02-rays-from-the-camera'))).toEqual([
      { kind: 'action', count: 6 },
      { kind: 'code', count: 1 },
      { kind: 'question', count: 2 },
      { kind: 'estimate', count: 1 },
      { kind: 'read', count: 1 },
    ]);
    // A challenge level: its rules to read, the ball to select, the target picture to match.
    expect(taskKindCounts(level('25-match-the-highlight'))).toEqual([
      { kind: 'action', count: 1 },
      { kind: 'challenge', count: 1 },
      { kind: 'read', count: 1 },
    ]);
  });

  it('counts only the tasks asked for', () => {
    const two = level('02-rays-from-the-camera');
    expect(taskKindCounts(two, ['the-screen', 'count-rays'])).toEqual([
      { kind: 'question', count: 1 },
      { kind: 'read', count: 1 },
    ]);
  });

  it('estimates minutes from the required tasks: the intro plus each kind’s stated time, up to a half minute', () => {
    const two = level('02-rays-from-the-camera');
    expect(estimatedMinutes(two, [])).toBe(INTRO_MINUTES);
    expect(estimatedMinutes(two, ['the-screen'])).toBe(1.5);
    expect(estimatedMinutes(two, ['the-screen', 'count-rays'])).toBe(Math.ceil((INTRO_MINUTES + MINUTES_PER_TASK.read + MINUTES_PER_TASK.question) * 2) / 2);
    // More required tasks never make a level shorter.
    for (const each of levels)
      expect(
        estimatedMinutes(
          each,
          each.tasks.map((task) => task.id),
        ),
      ).toBeGreaterThanOrEqual(estimatedMinutes(each, mandatoryTasks(each)));
  });
});
