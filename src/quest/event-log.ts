import { z } from 'zod';
import { badgeSchema } from './badges.ts';
import { TASK_KINDS } from './goal.ts';

/**
 * The research log (spec/classroom.md "Task timings"): every quest event with a timestamp,
 * kept with the progress and exported by the classroom tools (CSV, JSON, xAPI).
 *
 * Time. `t` is milliseconds since the log started (`startedAt`, wall-clock ISO 8601),
 * measured with the monotonic clock (performance.now()), so durations are right even when
 * the computer's clock is changed. A reload restarts performance.now(), so each page load
 * starts a session at max(the last `t`, the wall-clock time since `startedAt`): `t` never
 * goes back, and the time the page was closed counts as the gap it was. The wall-clock time
 * of each session's start is in its `session.started` event.
 *
 * Nothing is ever dropped: the log only grows. If storage is full the progress store says
 * so and the log stays in memory, ready to export.
 */

export const HOW_COMPLETED = ['done', 'shown', 'skipped'] as const;
/** done: by the learner; shown: by "show me" (or a quiz answer revealed); skipped: an optional task left out. */
export type HowCompleted = (typeof HOW_COMPLETED)[number];

export const HINT_STEPS = ['text', 'guidance', 'show-me'] as const;
export type HintStep = (typeof HINT_STEPS)[number];

const t = z.number().min(0);
const level = z.string();
const task = z.string();
/** `mandatory` is the level's flag; `required` whether it counted for the gate (a teacher's assignment may differ). */
const taskFlags = { mandatory: z.boolean(), required: z.boolean() };

export const loggedEventSchema = z.discriminatedUnion('type', [
  /** A page load: `at` is its wall-clock time. */
  z.strictObject({ t, type: z.literal('session.started'), at: z.iso.datetime() }),
  z.strictObject({ t, type: z.literal('level.opened'), level }),
  z.strictObject({ t, type: z.literal('level.closed'), level }),
  /** Every required task done: the next level opens. */
  z.strictObject({ t, type: z.literal('level.passed'), level }),
  /**
   * A task became the one to do (a required task) or available (an optional one, when the
   * level opens). `kind` (logs from 0.1 on; older ones lack it): info steps are read, not done.
   */
  z.strictObject({ t, type: z.literal('task.shown'), level, task, ...taskFlags, kind: z.enum(TASK_KINDS).optional() }),
  /** The learner's first action towards an optional task (its time starts here, not when the level opened). */
  z.strictObject({ t, type: z.literal('task.started'), level, task }),
  z.strictObject({ t, type: z.literal('task.completed'), level, task, ...taskFlags, how: z.enum(HOW_COMPLETED), points: z.number().min(0) }),
  /** A rung of the hint ladder; `trigger` says whether the learner asked or sat idle. */
  z.strictObject({ t, type: z.literal('hint.shown'), level, task, step: z.enum(HINT_STEPS), trigger: z.enum(['asked', 'idle']) }),
  /** "Explain more" opened, for a task or (task null) the level's intro. */
  z.strictObject({ t, type: z.literal('explanation.expanded'), level, task: task.nullable() }),
  z.strictObject({ t, type: z.literal('quiz.answered'), level, task, choice: z.number(), correct: z.boolean() }),
  z.strictObject({ t, type: z.literal('render.started'), level: level.nullable() }),
  z.strictObject({ t, type: z.literal('render.finished'), level: level.nullable(), ms: z.number().min(0) }),
  /** The tab was hidden or shown again: active time is the time in between hidden ones. */
  z.strictObject({ t, type: z.literal('tab.hidden') }),
  z.strictObject({ t, type: z.literal('tab.visible') }),
  z.strictObject({ t, type: z.literal('badge.earned'), badge: badgeSchema }),
]);

export type LoggedEvent = z.output<typeof loggedEventSchema>;

/** An event before it is stamped with its time. */
export type QuestEvent = LoggedEvent extends infer Event ? (Event extends LoggedEvent ? Omit<Event, 't'> : never) : never;

export const eventLogSchema = z
  .strictObject({ startedAt: z.iso.datetime(), events: z.array(loggedEventSchema) })
  .superRefine((log, context) => {
    log.events.forEach((event, index) => {
      if (index > 0 && event.t < log.events[index - 1].t) {
        context.addIssue({ code: 'custom', path: ['events', index, 't'], input: event.t, message: 'must not be earlier than the event before it' });
      }
    });
  });

export type EventLogData = z.output<typeof eventLogSchema>;

/** Where time comes from: performance.now() and Date.now() in the app, a fake clock in tests. */
export interface QuestClock {
  monotonicMs(): number;
  wallMs(): number;
}

export const systemClock: QuestClock = { monotonicMs: () => performance.now(), wallMs: () => Date.now() };

export function newEventLogData(clock: QuestClock): EventLogData {
  return { startedAt: new Date(clock.wallMs()).toISOString(), events: [] };
}

/** The log of this page load: continues a saved log with a new session. */
export class EventLog {
  private readonly startedAt: string;
  private readonly logged: LoggedEvent[];
  /** Log time minus monotonic time, fixed for this session. */
  private readonly offset: number;
  private last: number;

  constructor(
    saved: EventLogData,
    private readonly clock: QuestClock,
  ) {
    this.startedAt = saved.startedAt;
    this.logged = [...saved.events];
    this.last = this.logged.at(-1)?.t ?? 0;
    const sessionStart = Math.max(this.last, clock.wallMs() - Date.parse(saved.startedAt));
    this.offset = sessionStart - clock.monotonicMs();
    this.append({ type: 'session.started', at: new Date(clock.wallMs()).toISOString() });
  }

  /** The log's time now, in whole milliseconds; never less than the last event's. */
  now(): number {
    return Math.max(this.last, Math.round(this.offset + this.clock.monotonicMs()));
  }

  append(event: QuestEvent): LoggedEvent {
    this.last = this.now();
    const logged: LoggedEvent = { ...event, t: this.last };
    this.logged.push(logged);
    return logged;
  }

  get events(): readonly LoggedEvent[] {
    return this.logged;
  }

  /** The log for saving; it shares the (append-only) list of events. */
  get data(): EventLogData {
    return { startedAt: this.startedAt, events: this.logged };
  }
}
