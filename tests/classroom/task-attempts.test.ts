import { describe, expect, it } from 'vitest';
import { hintsOpened, readLog } from '../../src/classroom/task-attempts.ts';
import type { LoggedEvent } from '../../src/quest/event-log.ts';

const startedAt = '2026-03-09T09:00:00.000Z';
const task = (t: number, name: string, extra: Partial<LoggedEvent> = {}) =>
  ({ t, type: 'task.shown', level: 'L1', task: name, mandatory: true, required: true, ...extra }) as LoggedEvent;
const completed = (t: number, name: string, how: 'done' | 'shown' | 'skipped', points = 10): LoggedEvent => ({
  t,
  type: 'task.completed',
  level: 'L1',
  task: name,
  mandatory: true,
  required: true,
  how,
  points,
});

describe('reading a learner’s log as task attempts', () => {
  it('times an attempt from shown to completed, leaving out a hidden tab', () => {
    const { attempts } = readLog({
      startedAt,
      events: [
        { t: 0, type: 'session.started', at: startedAt },
        { t: 100, type: 'level.opened', level: 'L1' },
        task(1000, 'a'),
        { t: 2500, type: 'hint.offered', level: 'L1', task: 'a', step: 'text' },
        { t: 3000, type: 'hint.shown', level: 'L1', task: 'a', step: 'text', trigger: 'offered' },
        { t: 4000, type: 'tab.hidden' },
        { t: 9000, type: 'tab.visible' },
        { t: 9500, type: 'hint.shown', level: 'L1', task: 'a', step: 'guidance', trigger: 'asked' },
        completed(11_000, 'a', 'done'),
      ],
    });
    expect(attempts).toEqual([
      {
        level: 'L1',
        task: 'a',
        mandatory: true,
        kind: null,
        startedAt: '2026-03-09T09:00:01.000Z',
        completedAt: '2026-03-09T09:00:11.000Z',
        durationMs: 10_000,
        activeMs: 5000,
        how: 'done',
        points: 10,
        hintsText: 1,
        hintsGuidance: 1,
        hintsOffered: 1,
        quizAnswers: 0,
        quizCorrect: null,
        quizChoice: null,
        explanationOpens: 0,
      },
    ]);
  });

  it('counts a hint offered but not opened, or (an older log) shown by itself after idle time, as offered only', () => {
    const { attempts } = readLog({
      startedAt,
      events: [
        task(0, 'a'),
        { t: 45_000, type: 'hint.offered', level: 'L1', task: 'a', step: 'text' },
        completed(50_000, 'a', 'done'),
        task(50_000, 'b'),
        { t: 95_000, type: 'hint.shown', level: 'L1', task: 'b', step: 'text', trigger: 'idle' },
        { t: 99_000, type: 'hint.shown', level: 'L1', task: 'b', step: 'text', trigger: 'asked' },
        completed(100_000, 'b', 'done'),
      ],
    });
    expect(attempts.map(({ task: name, hintsOffered, hintsText }) => ({ name, hintsOffered, hintsText }))).toEqual([
      { name: 'a', hintsOffered: 1, hintsText: 0 },
      { name: 'b', hintsOffered: 1, hintsText: 1 },
    ]);
    expect(attempts.map(hintsOpened)).toEqual([0, 1]);
  });

  it('does not count the time the page was closed (a reload)', () => {
    const { attempts } = readLog({
      startedAt,
      events: [
        task(0, 'a'),
        { t: 2000, type: 'quiz.answered', level: 'L1', task: 'a', choice: 0, correct: false },
        { t: 62_000, type: 'session.started', at: '2026-03-09T09:01:02.000Z' },
        { t: 63_000, type: 'quiz.answered', level: 'L1', task: 'a', choice: 1, correct: true },
        completed(64_000, 'a', 'done'),
      ],
    });
    expect(attempts[0]).toMatchObject({ durationMs: 64_000, activeMs: 4000, quizAnswers: 2 });
  });

  it('ends an attempt unfinished when its level is closed, and starts a new one on return', () => {
    const { attempts, visits } = readLog({
      startedAt,
      events: [
        { t: 0, type: 'level.opened', level: 'L1' },
        task(0, 'a'),
        { t: 5000, type: 'level.closed', level: 'L1' },
        { t: 8000, type: 'level.opened', level: 'L1' },
        task(8000, 'a'),
        completed(9000, 'a', 'shown', 0),
        { t: 9000, type: 'level.passed', level: 'L1' },
        { t: 9500, type: 'level.closed', level: 'L1' },
      ],
    });
    expect(attempts.map((attempt) => [attempt.how, attempt.completedAt, attempt.durationMs])).toEqual([
      [null, null, 5000],
      ['shown', '2026-03-09T09:00:09.000Z', 1000],
    ]);
    expect(visits).toEqual([
      { level: 'L1', durationMs: 5000, activeMs: 5000, passed: false },
      { level: 'L1', durationMs: 1500, activeMs: 1500, passed: true },
    ]);
  });

  it('times what is still open at export up to the last event', () => {
    const { attempts, visits } = readLog({
      startedAt,
      events: [{ t: 0, type: 'level.opened', level: 'L1' }, task(1000, 'a'), { t: 4000, type: 'tab.hidden' }],
    });
    expect(attempts[0]).toMatchObject({ how: null, durationMs: 3000, activeMs: 3000 });
    expect(visits[0]).toMatchObject({ durationMs: 4000, passed: false });
  });
});
