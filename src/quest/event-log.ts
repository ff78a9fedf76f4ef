import { z } from 'zod';
import { reasonIssue } from '../scene/scene-issues.ts';
import { badgeSchema } from './badges.ts';
import { optionalCounts, starsSchema } from './challenge-par.ts';
import { TASK_KINDS } from './goal.ts';
import { ID_MAX } from './kebab-id.ts';

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
 *
 * Tabs. Each page load is a session with a random id; its events are numbered
 * `<session>.<n>`, so that two tabs writing the same saved log can merge their events by id
 * (progress-merge.ts) instead of overwriting each other. Events saved before ids existed
 * get `saved.<index>` when loaded: every tab loading the same old log numbers it the same way.
 */

/** A session id (up to 16 letters and digits), a dot and the event's number in its session. */
const EVENT_ID = /^[a-z0-9]{1,16}\.\d{1,9}$/;

export const HOW_COMPLETED = ['done', 'shown', 'skipped'] as const;
/** done: by the learner; shown: by "show me" (or a quiz answer revealed); skipped: an optional task left out. */
export type HowCompleted = (typeof HOW_COMPLETED)[number];

export const HINT_STEPS = ['text', 'guidance', 'show-me'] as const;
export type HintStep = (typeof HINT_STEPS)[number];

/** The rungs the app offers by itself after idle time ("show me" is only ever asked for). */
export const OFFERED_STEPS = ['text', 'guidance'] as const;
export type OfferedStep = (typeof OFFERED_STEPS)[number];

/**
 * Why a hint was shown. `asked`: the learner pressed the ladder's button; `offered`: the
 * learner opened a hint the app offered after idle time (`hint.offered`). Both are opened
 * by the learner and count as used. `idle` is only in logs from before offers existed: the
 * app showed the rung by itself after idle time, without the learner asking. It still loads;
 * the exports and the dashboard read it as offered, not opened (docs/classroom.md), while the
 * saved progress keeps the hint count it had (its "No hints needed" badge is not given back).
 */
export const HINT_TRIGGERS = ['asked', 'offered', 'idle'] as const;
export type HintTrigger = (typeof HINT_TRIGGERS)[number];

const t = z.number().min(0);
/** Level and task ids are kebab ids of at most 64 characters (kebab-id.ts); the log allows any short text. */
const level = z.string().max(ID_MAX);
const task = z.string().max(ID_MAX);
/** `<session>.<n>`; optional so that logs saved before ids existed still read. */
const id = z.string().regex(EVENT_ID).optional();
/** `mandatory` is the level's flag; `required` whether it counted for the gate (a teacher's assignment may differ). */
const taskFlags = { mandatory: z.boolean(), required: z.boolean() };

export const loggedEventSchema = z.discriminatedUnion('type', [
  /** A page load: `at` is its wall-clock time. */
  z.strictObject({ t, id, type: z.literal('session.started'), at: z.iso.datetime() }),
  z.strictObject({ t, id, type: z.literal('level.opened'), level }),
  z.strictObject({ t, id, type: z.literal('level.closed'), level }),
  /** Every required task done: the next level opens. */
  z.strictObject({ t, id, type: z.literal('level.passed'), level }),
  /**
   * A task became the one to do (a required task) or available (an optional one, when the
   * level opens). `kind` (logs from 0.1 on; older ones lack it): info steps are read, not done.
   */
  z.strictObject({ t, id, type: z.literal('task.shown'), level, task, ...taskFlags, kind: z.enum(TASK_KINDS).optional() }),
  /** The learner's first action towards an optional task (its time starts here, not when the level opened). */
  z.strictObject({ t, id, type: z.literal('task.started'), level, task }),
  /** `stars`: a challenge matched by the learner, its golf score (challenge-par.ts; later logs). */
  z.strictObject({
    t,
    id,
    type: z.literal('task.completed'),
    level,
    task,
    ...taskFlags,
    how: z.enum(HOW_COMPLETED),
    points: z.number().min(0),
    stars: starsSchema.optional(),
  }),
  /**
   * After idle time on its task, the app offered the next rung: the learner sees that a hint
   * is ready, not the hint. It costs nothing; opening it is a `hint.shown` with trigger
   * `offered`. (Older logs have none: they show the rung at once, trigger `idle`.)
   */
  z.strictObject({ t, id, type: z.literal('hint.offered'), level, task, step: z.enum(OFFERED_STEPS) }),
  /** A rung of the hint ladder the learner opened; `trigger` says how (HINT_TRIGGERS). */
  z.strictObject({ t, id, type: z.literal('hint.shown'), level, task, step: z.enum(HINT_STEPS), trigger: z.enum(HINT_TRIGGERS) }),
  /** "Explain more" opened, for a task or (task null) the level's intro. */
  z.strictObject({ t, id, type: z.literal('explanation.expanded'), level, task: task.nullable() }),
  /** A prediction: a quiz's `choice` (its position in the level file) or an estimate's `value`. */
  z.strictObject({ t, id, type: z.literal('quiz.answered'), level, task, choice: z.number().optional(), value: z.number().optional(), correct: z.boolean() }),
  /** After observing, a learner whose prediction was wrong says what they saw (logs from 0.2 on). */
  z.strictObject({ t, id, type: z.literal('quiz.reflected'), level, task, choice: z.number().optional(), value: z.number().optional(), correct: z.boolean() }),
  /** The explanation of a prediction was read after observing, and the learner moved on. */
  z.strictObject({ t, id, type: z.literal('quiz.explained'), level, task }),
  z.strictObject({ t, id, type: z.literal('render.started'), level: level.nullable() }),
  z.strictObject({ t, id, type: z.literal('render.finished'), level: level.nullable(), ms: z.number().min(0) }),
  /**
   * A challenge's pictures compared after a render (logs from issue 41 on): `difference` is the
   * measure, within the threshold or not; the renders, changes and rays counted since the
   * challenge started, this render included, the challenge task and the match score the
   * learner read (challenge-closeness.ts matchScore) (later logs; the first ones lack them).
   */
  z.strictObject({
    t,
    id,
    type: z.literal('challenge.compared'),
    level: level.nullable(),
    difference: z.number().min(0),
    ...optionalCounts,
    task: task.optional(),
    score: z.number().min(0).max(100).optional(),
  }),
  /**
   * A code lab's Run tests graded (issue 43; logs from then on): the lab, the cases passed of
   * how many, the first failing case's kind (null: all passed), and the open level's code task.
   */
  z.strictObject({
    t,
    id,
    type: z.literal('code.graded'),
    level: level.nullable(),
    task: task.optional(),
    lab: z.string().min(1).max(ID_MAX),
    passed: z.int().min(0),
    total: z.int().min(1),
    failed: z.string().min(1).max(ID_MAX).nullable(),
  }),
  /** The tab was hidden or shown again: active time is the time in between hidden ones. */
  z.strictObject({ t, id, type: z.literal('tab.hidden') }),
  z.strictObject({ t, id, type: z.literal('tab.visible') }),
  z.strictObject({ t, id, type: z.literal('badge.earned'), badge: badgeSchema }),
]);

/** An event as logged: with its time and, once loaded or appended, its id. */
export type LoggedEvent = z.output<typeof loggedEventSchema>;

/** An event before it is stamped with its time and id. */
export type QuestEvent = LoggedEvent extends infer Event ? (Event extends LoggedEvent ? Omit<Event, 't' | 'id'> : never) : never;

export const eventLogSchema = z.strictObject({ startedAt: z.iso.datetime(), events: z.array(loggedEventSchema) }).superRefine((log, context) => {
  log.events.forEach((event, index) => {
    if (index > 0 && event.t < log.events[index - 1].t) {
      context.addIssue(reasonIssue(['events', index, 't'], event.t, { code: 'earlierThanBefore' }));
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

/** Eight random letters and digits: two tabs opened in the same millisecond still differ. */
export function randomSessionId(): string {
  const bytes = crypto.getRandomValues(new Uint8Array(8));
  return Array.from(bytes, (byte) => (byte % 36).toString(36)).join('');
}

/** The session part of an event id (`abc123.7` → `abc123`). */
export function sessionOf(eventId: string): string {
  return eventId.slice(0, eventId.indexOf('.'));
}

/** The number part of an event id (`abc123.7` → 7). */
export function numberOf(eventId: string): number {
  return Number(eventId.slice(eventId.indexOf('.') + 1));
}

/** Gives events saved before ids existed the ids every tab gives them: `saved.<index>`. */
export function withIds(events: readonly LoggedEvent[]): LoggedEvent[] {
  return events.map((event, index) => (event.id === undefined ? { ...event, id: `saved.${index}` } : event));
}

/** The log of this page load: continues a saved log with a new session. */
export class EventLog {
  private startedAt: string;
  private logged: LoggedEvent[];
  /** Log time minus monotonic time, fixed for this session (moved only when a merge moves the log's start). */
  private offset: number;
  private last: number;
  private count = 0;

  constructor(
    saved: EventLogData,
    private readonly clock: QuestClock,
    readonly session: string = randomSessionId(),
  ) {
    this.startedAt = saved.startedAt;
    this.logged = withIds(saved.events);
    this.last = this.logged.at(-1)?.t ?? 0;
    const sessionStart = Math.max(this.last, clock.wallMs() - Date.parse(saved.startedAt));
    this.offset = sessionStart - clock.monotonicMs();
    this.append({ type: 'session.started', at: new Date(clock.wallMs()).toISOString() });
  }

  /**
   * Takes over a merged log (progress-merge.ts) that holds every event of this one: other
   * tabs' events join the list, and when the merged log starts earlier this session's
   * times move with it, so its clock keeps running on the merged log's time.
   */
  adopt(merged: EventLogData): void {
    const shift = Date.parse(this.startedAt) - Date.parse(merged.startedAt);
    this.startedAt = merged.startedAt;
    this.offset += shift;
    this.logged = [...merged.events];
    this.last = Math.max(this.last + shift, this.logged.at(-1)?.t ?? 0);
  }

  /** The log's time now, in whole milliseconds; never less than the last event's. */
  now(): number {
    return Math.max(this.last, Math.round(this.offset + this.clock.monotonicMs()));
  }

  append(event: QuestEvent): LoggedEvent {
    this.last = this.now();
    const logged: LoggedEvent = { ...event, t: this.last, id: `${this.session}.${this.count++}` };
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
