// The dashboard's challenge table: how close a class got to a challenge's target, from the
// learners' files, and nothing for a level without a challenge anyone rendered in.
import { afterEach, describe, expect, it } from 'vitest';
import type { ClassRecord } from '../../src/classroom/dashboard-record.ts';
import type { TaskAttempt } from '../../src/classroom/task-attempts.ts';
import '../../src/ui/classroom/dashboard/rt-dashboard-challenges.ts';
import { mount, unmountAll } from './mount.ts';

afterEach(unmountAll);

const attempt = (how: TaskAttempt['how'], scores: number[], stars: 1 | 2 | 3 | null = null): TaskAttempt => ({
  level: 'L25',
  task: 'match',
  mandatory: true,
  kind: 'do',
  startedAt: '2025-03-04T09:00:00.000Z',
  completedAt: how === null ? null : '2025-03-04T09:01:00.000Z',
  durationMs: 60_000,
  activeMs: 60_000,
  how,
  points: 0,
  hintsText: 0,
  hintsGuidance: 0,
  hintsOffered: 0,
  quizAnswers: 0,
  quizCorrect: null,
  quizChoice: null,
  explanationOpens: 0,
  challenge: { renders: scores.length, changes: scores.length, rays: 0, scores, stars },
});
const learner = (attempts: TaskAttempt[]) => ({ attempts, visits: [] }) as unknown as ClassRecord;

describe('rt-dashboard-challenges', () => {
  it("shows each learner's best score (the task by its title), the stars of those who matched and where the others stopped", async () => {
    const table = await mount('rt-dashboard-challenges', {
      level: 'L25',
      taskName: (task: string) => (task === 'match' ? 'Match the target' : task),
      records: [learner([attempt('done', [20, 80], 3)]), learner([attempt(null, [10, 40])]), learner([attempt(null, [50]), attempt('done', [76], 1)])],
    });
    const row = table.shadowRoot!.querySelector('tr[data-task="match"]')!;
    expect([...row.querySelectorAll('th, td')].map((cell) => cell.textContent!.trim())).toEqual([
      'Match the target',
      '3',
      '40, 76, 80 (2 reached 75)',
      '2 (1 / 0 / 1)',
      '40',
    ]);
  });

  it('shows nothing for a level without a challenge anyone rendered in', async () => {
    const table = await mount('rt-dashboard-challenges', { level: 'L1', records: [learner([attempt('done', [80], 3)])] });
    expect(table.shadowRoot!.querySelector('table')).toBeNull();
  });
});
