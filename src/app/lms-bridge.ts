import { elementsOf, exitValues, interactionValues, statusValues, type CmiValue } from '../classroom/scorm/cmi-values.ts';
import type { LmsConnection } from '../classroom/scorm/lms-api.ts';
import { lmsReport, type LmsInteraction, type ReportScope } from '../classroom/scorm/lms-report.ts';
import { resumeProgress, SUSPEND_DATA_LIMIT, suspendProgress, type SuspendedPart } from '../classroom/scorm/suspend-data.ts';
import { playableLevels } from '../quest/level-index.ts';
import type { Progress } from '../quest/progress.ts';
import type { QuestSession } from './quest-session.ts';

/**
 * The game inside a school's learning platform (SCORM 1.2 or 2004, docs/classroom.md):
 *
 * - When the game's first session starts: the platform's session is opened; when the
 *   platform says this launch resumes an earlier one (cmi.entry `resume`), the progress it
 *   kept in its suspend data joins the browser's (merged as two tabs' are), and the game
 *   starts again from it (the finished screen, the level to resume). The platform is the
 *   record of who plays: when the browser's progress of the assignment was someone else's
 *   (a shared school computer), it is replaced, not merged.
 * - While the learner plays: after every change of the report (lms-report.ts: completion,
 *   score, one interaction per task and quiz) the changed values are set and committed,
 *   together with the session time, the exit (always `suspend`: cmi-values.ts) and the
 *   suspend data.
 * - When the page goes (pagehide): a last commit, then the platform's session ends.
 */

/** Which learner of the platform this browser's progress of an assignment belongs to. */
const learnerKey = (progressKey: string) => `rtq.lms-learner.${progressKey}`;

/** The platform's session opened, or null when the platform would not open it. */
export function startLmsBridge(lms: LmsConnection, window: Window): LmsBridge | null {
  if (!lms.initialize()) {
    console.warn(`The learning platform did not open its session (error ${lms.lastError()}): nothing is reported to it.`);
    return null;
  }
  const bridge = new LmsBridge(lms, window);
  window.addEventListener('pagehide', () => bridge.finish());
  window.document.addEventListener('visibilitychange', () => {
    if (window.document.visibilityState === 'hidden') bridge.commit();
  });
  return bridge;
}

/** Whether any task of `progress` is completed. */
const hasWork = (progress: Progress) => Object.values(progress.levels).some((level) => Object.keys(level.tasks).length > 0);

class LmsBridge {
  private readonly startedMs = performance.now();
  private readonly startedWallMs = Date.now();
  /** Each value as last set, so that only changes are sent. */
  private readonly sent = new Map<string, string>();
  /** Each interaction's position in the platform's list, by its id. */
  private readonly positions = new Map<string, number>();
  private interactionCount: number;
  private session: QuestSession | null = null;
  private restored = false;
  private toldSuspend: SuspendedPart = 'full';
  private finished = false;

  constructor(
    private readonly lms: LmsConnection,
    private readonly window: Window,
  ) {
    this.interactionCount = Number(lms.get('cmi.interactions._count')) || 0;
    // SCORM 2004 lets us read the interactions of earlier launches: a task is updated in its place, not added twice.
    if (lms.version === '2004') for (let n = 0; n < this.interactionCount; n++) this.positions.set(lms.get(`cmi.interactions.${n}.id`), n);
  }

  follow(session: QuestSession): () => void {
    this.session = session;
    if (!this.restored) {
      this.restored = true;
      this.restore(session);
    }
    const { assignment } = session;
    const levels = playableLevels(session.catalog).filter((level) => !assignment || assignment.levels.includes(level.id));
    const scope: ReportScope = { levels, requiredTasks: assignment?.requiredTasks };
    let seen = -1;
    const changed = () => {
      // The report changes only with the log: every completion and answer is an event.
      if (session.engine.events.length === seen) return;
      seen = session.engine.events.length;
      this.report(session, scope);
    };
    const stop = session.subscribe(changed);
    changed();
    return () => {
      stop();
      if (this.session === session) this.session = null;
    };
  }

  /** The platform's suspend data into the session: merged with the learner's own progress, or replacing someone else's. */
  private restore(session: QuestSession): void {
    const elements = elementsOf(this.lms.version);
    const learner = this.lms.get(elements.learnerId);
    const resumed = this.lms.get(elements.entry) === 'resume' ? resumeProgress(this.lms.get('cmi.suspend_data'), new Date().toISOString()) : null;
    const key = learnerKey(session.progressKey);
    let owner: string | null = null;
    try {
      owner = this.window.localStorage.getItem(key);
      this.window.localStorage.setItem(key, learner);
    } catch {
      // No storage: the progress is this visit's only, and the platform's.
    }
    const someoneElses = owner !== learner && hasWork(session.engine.progress);
    if (someoneElses) {
      if (resumed) session.importText(JSON.stringify(resumed));
      else session.reset();
    } else if (resumed) {
      session.engine.absorb(resumed);
    }
    if (someoneElses || resumed) session.start();
  }

  /** Sets the values that changed; commits when any did. */
  private report(session: QuestSession, scope: ReportScope): void {
    if (this.finished) return;
    const report = lmsReport(session.engine.progress, scope);
    const location = session.mode.kind === 'level' ? session.mode.id : null;
    const values = [...statusValues(this.lms.version, report, location), ...report.interactions.flatMap((interaction) => this.interactionAt(interaction))];
    if (values.filter(([element, value]) => this.set(element, value)).length > 0) this.commit();
  }

  private interactionAt(interaction: LmsInteraction): CmiValue[] {
    let position = this.positions.get(interaction.id);
    if (position === undefined) {
      // SCORM 1.2's interactions cannot be read back: one that ended before this launch was sent by the launch it happened in.
      if (this.lms.version === '1.2' && Date.parse(interaction.timestamp) + interaction.latencyMs < this.startedWallMs) return [];
      position = this.interactionCount++;
      this.positions.set(interaction.id, position);
    }
    return interactionValues(this.lms.version, position, interaction);
  }

  /** Sets one value unless it is already set; whether it was sent. */
  private set(element: string, value: string): boolean {
    if (this.sent.get(element) === value) return false;
    this.sent.set(element, value);
    if (!this.lms.set(element, value)) console.warn(`The learning platform refused ${element} = ${JSON.stringify(value)} (error ${this.lms.lastError()})`);
    return true;
  }

  /** The session time, the exit mode and the suspend data, then the platform's commit. */
  commit(): void {
    if (this.finished) return;
    for (const [element, value] of exitValues(this.lms.version, performance.now() - this.startedMs)) this.set(element, value);
    if (this.session) this.suspend(this.session);
    this.lms.commit();
  }

  private suspend(session: QuestSession): void {
    const { text, part } = suspendProgress(session.engine.progress, SUSPEND_DATA_LIMIT[this.lms.version]);
    if (part !== this.toldSuspend) {
      this.toldSuspend = part;
      if (part !== 'full')
        console.warn(
          `The progress does not fit in the learning platform's suspend data: ${part === 'tasks' ? 'only the completed tasks are kept there' : 'the last that did fit is kept'}.`,
        );
    }
    if (part !== 'none') this.set('cmi.suspend_data', text);
  }

  /** The page goes: the last values, then the end of the platform's session (no call may follow it). */
  finish(): void {
    if (this.finished) return;
    this.session?.flush();
    this.commit();
    this.finished = true;
    this.lms.terminate();
  }
}
