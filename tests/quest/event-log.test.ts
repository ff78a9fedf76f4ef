import { describe, expect, it } from 'vitest';
import { EventLog, eventLogSchema, newEventLogData } from '../../src/quest/event-log.ts';
import { FakeClock } from '../support/quest-fixtures.ts';

describe('the event log', () => {
  it('stamps events with milliseconds since the log started, from the monotonic clock', () => {
    const clock = new FakeClock();
    const log = new EventLog(newEventLogData(clock), clock, 'tab1');
    clock.advance(1234.4);
    log.append({ type: 'level.opened', level: 'first' });
    // The wall clock jumps back an hour (a clock change): durations do not notice.
    clock.wall -= 3_600_000;
    clock.monotonic += 500;
    log.append({ type: 'level.closed', level: 'first' });
    expect(log.data.startedAt).toBe('2025-03-01T09:00:00.000Z');
    expect(log.events).toEqual([
      { t: 0, id: 'tab1.0', type: 'session.started', at: '2025-03-01T09:00:00.000Z' },
      { t: 1234, id: 'tab1.1', type: 'level.opened', level: 'first' },
      { t: 1734, id: 'tab1.2', type: 'level.closed', level: 'first' },
    ]);
  });

  it('continues after a reload: a new session at the wall-clock gap, never earlier than the last event', () => {
    const clock = new FakeClock();
    const log = new EventLog(newEventLogData(clock), clock);
    clock.advance(5_000);
    log.append({ type: 'tab.hidden' });
    const saved = JSON.parse(JSON.stringify(log.data));

    // Reopened a minute later: performance.now() starts again near 0.
    const later = new FakeClock();
    later.monotonic = 20;
    later.wall = clock.wall + 60_000;
    const resumed = new EventLog(saved, later, 'tab2');
    later.advance(100);
    resumed.append({ type: 'tab.visible' });
    expect(resumed.events.slice(-2)).toEqual([
      { t: 65_000, id: 'tab2.0', type: 'session.started', at: '2025-03-01T09:01:05.000Z' },
      { t: 65_100, id: 'tab2.1', type: 'tab.visible' },
    ]);

    // Reopened with the computer's clock set back before the log began: time still only moves on.
    const wrongClock = new FakeClock();
    wrongClock.wall = clock.wall - 86_400_000;
    const again = new EventLog(resumed.data, wrongClock);
    expect(again.events.at(-1)?.t).toBe(65_100);
  });

  it('keeps every event: the log only grows', () => {
    const clock = new FakeClock();
    const log = new EventLog(newEventLogData(clock), clock);
    for (let i = 0; i < 20_000; i++) {
      clock.advance(1);
      log.append({ type: 'render.started', level: null });
    }
    expect(log.events).toHaveLength(20_001);
    const times = log.events.map((event) => event.t);
    expect(times.every((t, i) => i === 0 || t >= times[i - 1])).toBe(true);
  });

  it('numbers events saved before ids existed the same way in every tab', () => {
    const clock = new FakeClock();
    const saved = {
      startedAt: '2025-03-01T09:00:00.000Z',
      events: [
        { t: 0, type: 'tab.hidden' as const },
        { t: 5, type: 'tab.visible' as const },
      ],
    };
    const first = new EventLog(saved, clock, 'one');
    const second = new EventLog(saved, clock, 'two');
    expect(first.events.slice(0, 2).map((event) => event.id)).toEqual(['saved.0', 'saved.1']);
    expect(second.events.slice(0, 2)).toEqual(first.events.slice(0, 2));
    expect(first.events[2].id).toBe('one.0');
  });

  it('validates saved logs: known events only, times in order', () => {
    const startedAt = '2025-03-01T09:00:00.000Z';
    expect(
      eventLogSchema.safeParse({
        startedAt,
        events: [
          { t: 5, type: 'tab.hidden' },
          { t: 4, type: 'tab.visible' },
        ],
      }).success,
    ).toBe(false);
    expect(eventLogSchema.safeParse({ startedAt, events: [{ t: 5, type: 'tab.spun' }] }).success).toBe(false);
    expect(eventLogSchema.safeParse({ startedAt, events: [{ t: 5, id: 'x'.repeat(17) + '.1', type: 'tab.hidden' }] }).success).toBe(false);
    expect(eventLogSchema.safeParse({ startedAt, events: [{ t: 5, type: 'level.opened', level: 'a'.repeat(65) }] }).success).toBe(false);
    expect(
      eventLogSchema.safeParse({
        startedAt,
        events: [{ t: 5, type: 'task.completed', level: 'a', task: 'b', mandatory: true, required: true, how: 'done', points: 10 }],
      }).success,
    ).toBe(true);
  });

  it('keeps hints offered and opened apart, and still reads a hint shown by itself in an older log', () => {
    const startedAt = '2025-03-01T09:00:00.000Z';
    const valid = (event: Record<string, unknown>) => eventLogSchema.safeParse({ startedAt, events: [{ t: 5, level: 'a', task: 'b', ...event }] }).success;
    expect(valid({ type: 'hint.offered', step: 'text' })).toBe(true);
    expect(valid({ type: 'hint.offered', step: 'guidance' })).toBe(true);
    // "Show me" is only ever asked for, and an offer is not a hint shown.
    expect(valid({ type: 'hint.offered', step: 'show-me' })).toBe(false);
    expect(valid({ type: 'hint.offered', step: 'text', trigger: 'idle' })).toBe(false);
    expect(valid({ type: 'hint.shown', step: 'text', trigger: 'asked' })).toBe(true);
    expect(valid({ type: 'hint.shown', step: 'text', trigger: 'offered' })).toBe(true);
    // Saved before offers existed: the rung appeared by itself after idle time.
    expect(valid({ type: 'hint.shown', step: 'guidance', trigger: 'idle' })).toBe(true);
    expect(valid({ type: 'hint.shown', step: 'text', trigger: 'bored' })).toBe(false);
  });
});
