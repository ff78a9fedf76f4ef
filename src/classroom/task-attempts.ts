import type { EventLogData, HowCompleted, LoggedEvent } from '../quest/event-log.ts';
import type { TaskKind } from '../quest/goal.ts';
import { addComparison, type ChallengeTries } from './challenge-attempt.ts';
import { addCodeRun, type CodeRuns } from './code-lab-attempt.ts';

/**
 * A learner's event log read back as task attempts and level visits: what the dashboard
 * counts. An attempt at a required task runs from `task.shown` (the moment it became the
 * learner's to do) to its `task.completed`, or ends unfinished when its level is closed
 * first (the learner left; opening the level again starts a new attempt).
 *
 * An optional task is shown when its level opens, but the learner may never look at it:
 * its attempt starts at the learner's first move towards it (`task.started`; in logs from
 * before that event, the first hint, quiz answer, explanation or completion of the task).
 * An optional task nobody touched has no attempt at all.
 *
 * `mandatory` is whether the task counted for passing the level for this learner (the
 * teacher's choice of required tasks, else the level's), and never for an info step,
 * which is read rather than done.
 *
 * Active time is the time the tab was visible: a hidden tab (tab.hidden → tab.visible) and
 * a closed page (the last event before a reload → its session.started) do not count.
 */

export interface TaskAttempt {
  level: string;
  task: string;
  /** Required to pass the level, and not an info step. */
  mandatory: boolean;
  /** info, quiz or do; null when the log does not say (logs before 0.1). */
  kind: TaskKind | null;
  /** ISO 8601 wall-clock time, from the log's start plus its monotonic time. */
  startedAt: string;
  /** Null when the attempt ended unfinished. */
  completedAt: string | null;
  durationMs: number;
  activeMs: number;
  /** Null when the attempt ended unfinished; 'shown' is a "show me". */
  how: HowCompleted | null;
  points: number;
  /** Text hints the learner opened (asked for, or opened from an offer); they count as used. */
  hintsText: number;
  /** "Show me where" rings the learner opened, the same way. */
  hintsGuidance: number;
  /**
   * Hints the app offered after idle time, opened or not. In logs from before offers, a
   * rung the app showed by itself after idle time (trigger `idle`) counts here, not as opened:
   * the learner did not ask for it.
   */
  hintsOffered: number;
  /** Quiz answers given (a wrong prediction and then the right one is 2). */
  quizAnswers: number;
  /** Whether the last quiz answer was right; null when no answer was given (not a quiz, or "show me"). */
  quizCorrect: boolean | null;
  /** The position in the level file of the last choice answered (quiz-options.ts names it a, b, …); null for none or a number. */
  quizChoice: number | null;
  /** "Explain more" opened for the task, during the attempt or after it ended (then counted on the task's last attempt). */
  explanationOpens: number;
  /** A challenge task's tries in this attempt (challenge-attempt.ts); absent for other tasks and in logs before they were recorded. */
  challenge?: ChallengeTries;
  /** A code lab task's runs in this attempt (code-lab-attempt.ts); absent for other tasks and in logs before they were recorded. */
  code?: CodeRuns;
}

export interface LevelVisit {
  level: string;
  durationMs: number;
  activeMs: number;
  /** The level's required tasks were all done during this visit. */
  passed: boolean;
}

export interface ReadLog {
  attempts: TaskAttempt[];
  visits: LevelVisit[];
}

/** Time spans when the learner could not have been looking: hidden tab, closed page. */
function inactiveSpans(events: readonly LoggedEvent[]): [number, number][] {
  const spans: [number, number][] = [];
  let hiddenSince: number | null = null;
  events.forEach((event, index) => {
    if (event.type === 'tab.hidden') hiddenSince ??= event.t;
    else if (event.type === 'tab.visible' || event.type === 'session.started') {
      // A reload while hidden ends the hidden span; otherwise the page was closed since the last event.
      const from = hiddenSince ?? (event.type === 'session.started' && index > 0 ? events[index - 1].t : null);
      if (from !== null && event.t > from) spans.push([from, event.t]);
      hiddenSince = null;
    }
  });
  if (hiddenSince !== null) spans.push([hiddenSince, Number.POSITIVE_INFINITY]);
  return spans;
}

/** The visible time between `from` and `to`. */
function activeBetween(spans: readonly [number, number][], from: number, to: number): number {
  let inactive = 0;
  for (const [start, end] of spans) inactive += Math.max(0, Math.min(end, to) - Math.max(start, from));
  return to - from - inactive;
}

const key = (level: string, task: string) => `${level}\u0000${task}`;

/** Attempts and level visits in the order they started. */
export function readLog(log: EventLogData): ReadLog {
  const spans = inactiveSpans(log.events);
  const origin = Date.parse(log.startedAt);
  const iso = (t: number) => new Date(origin + t).toISOString();
  const attempts: TaskAttempt[] = [];
  const visits: LevelVisit[] = [];
  // The open ones with the time they started.
  const openAttempts = new Map<string, { attempt: TaskAttempt; from: number }>();
  const openVisits = new Map<string, { visit: LevelVisit; from: number }>();
  // Each task's latest attempt, open or ended: an explanation is often read after the answer.
  const lastAttempts = new Map<string, TaskAttempt>();
  // Optional tasks shown but not yet touched: their attempt starts at the first move.
  const untouched = new Map<string, { level: string; task: string; kind: TaskKind | null }>();
  const timed = (from: number, to: number) => ({ durationMs: to - from, activeMs: activeBetween(spans, from, to) });

  const closeAttempt = (open: { attempt: TaskAttempt; from: number }, t: number, finished?: { how: HowCompleted; points: number }) => {
    Object.assign(open.attempt, timed(open.from, t), finished && { completedAt: iso(t), ...finished });
    openAttempts.delete(key(open.attempt.level, open.attempt.task));
  };
  const startAttempt = (level: string, task: string, mandatory: boolean, kind: TaskKind | null, t: number) => {
    const attempt: TaskAttempt = {
      level,
      task,
      mandatory: mandatory && kind !== 'info',
      kind,
      startedAt: iso(t),
      completedAt: null,
      durationMs: 0,
      activeMs: 0,
      how: null,
      points: 0,
      hintsText: 0,
      hintsGuidance: 0,
      hintsOffered: 0,
      quizAnswers: 0,
      quizCorrect: null,
      quizChoice: null,
      explanationOpens: 0,
    };
    lastAttempts.set(key(level, task), attempt);
    openAttempts.set(key(level, task), { attempt, from: t });
    attempts.push(attempt);
  };
  /** The optional task's first move, if it is one: its attempt starts now. */
  const touch = (level: string, task: string | null, t: number) => {
    const waiting = task === null ? undefined : untouched.get(key(level, task));
    if (!waiting) return;
    untouched.delete(key(level, task!));
    startAttempt(waiting.level, waiting.task, false, waiting.kind, t);
  };
  const closeVisit = (open: { visit: LevelVisit; from: number }, t: number) => {
    Object.assign(open.visit, timed(open.from, t));
    openVisits.delete(open.visit.level);
  };

  for (const event of log.events) {
    switch (event.type) {
      case 'level.opened':
        if (!openVisits.has(event.level)) {
          const visit: LevelVisit = { level: event.level, durationMs: 0, activeMs: 0, passed: false };
          openVisits.set(event.level, { visit, from: event.t });
          visits.push(visit);
        }
        break;
      case 'level.passed': {
        const open = openVisits.get(event.level);
        if (open) open.visit.passed = true;
        break;
      }
      case 'level.closed': {
        const visit = openVisits.get(event.level);
        if (visit) closeVisit(visit, event.t);
        for (const open of [...openAttempts.values()]) if (open.attempt.level === event.level) closeAttempt(open, event.t);
        for (const [id, waiting] of [...untouched]) if (waiting.level === event.level) untouched.delete(id);
        break;
      }
      case 'task.shown':
        if (openAttempts.has(key(event.level, event.task))) break;
        if (event.required) startAttempt(event.level, event.task, true, event.kind ?? null, event.t);
        else untouched.set(key(event.level, event.task), { level: event.level, task: event.task, kind: event.kind ?? null });
        break;
      case 'task.started':
        touch(event.level, event.task, event.t);
        break;
      case 'explanation.expanded': {
        touch(event.level, event.task, event.t);
        const attempt = event.task === null ? undefined : lastAttempts.get(key(event.level, event.task));
        if (attempt) attempt.explanationOpens++;
        break;
      }
      case 'task.completed': {
        touch(event.level, event.task, event.t);
        const attempt = openAttempts.get(key(event.level, event.task));
        if (attempt) closeAttempt(attempt, event.t, { how: event.how, points: event.points });
        if (attempt?.attempt.challenge && event.stars !== undefined) attempt.attempt.challenge.stars = event.stars;
        break;
      }
      case 'hint.offered': {
        // The app's doing, not a move of the learner's: it starts no optional task's time.
        const attempt = openAttempts.get(key(event.level, event.task))?.attempt;
        if (attempt) attempt.hintsOffered++;
        break;
      }
      case 'hint.shown': {
        // An older log's rung that came by itself after idle time: offered, not opened.
        const opened = event.trigger !== 'idle';
        if (opened) touch(event.level, event.task, event.t);
        const attempt = openAttempts.get(key(event.level, event.task))?.attempt;
        if (!attempt) break;
        if (!opened) attempt.hintsOffered++;
        // The show-me rung is counted when it is used: the task is then completed as 'shown'.
        else if (event.step === 'text') attempt.hintsText++;
        else if (event.step === 'guidance') attempt.hintsGuidance++;
        break;
      }
      case 'challenge.compared': {
        const attempt = event.level === null || event.task === undefined ? undefined : openAttempts.get(key(event.level, event.task))?.attempt;
        if (attempt) attempt.challenge = addComparison(attempt.challenge, event);
        break;
      }
      case 'code.graded': {
        // A run is a move towards the task: an optional code lab's attempt starts at its first.
        if (event.level !== null && event.task !== undefined) touch(event.level, event.task, event.t);
        const attempt = event.level === null || event.task === undefined ? undefined : openAttempts.get(key(event.level, event.task))?.attempt;
        if (attempt) attempt.code = addCodeRun(attempt.code, event);
        break;
      }
      case 'quiz.answered': {
        touch(event.level, event.task, event.t);
        const attempt = openAttempts.get(key(event.level, event.task))?.attempt;
        if (attempt) {
          attempt.quizAnswers++;
          attempt.quizCorrect = event.correct;
          attempt.quizChoice = event.choice ?? null;
        }
        break;
      }
    }
  }
  // Still open when the file was exported: timed up to the last event.
  const lastT = log.events.at(-1)?.t ?? 0;
  for (const open of [...openAttempts.values()]) closeAttempt(open, lastT);
  for (const open of [...openVisits.values()]) closeVisit(open, lastT);
  return { attempts, visits };
}

/** The hints an attempt counts as used (text and guidance the learner opened; "show me" is its `how`). */
export function hintsOpened(attempt: Pick<TaskAttempt, 'hintsText' | 'hintsGuidance'>): number {
  return attempt.hintsText + attempt.hintsGuidance;
}
