import type { Assignment } from '../classroom/assignment.ts';
import type { ConceptTestAnswers, ConceptTestSubmission } from '../classroom/concept-test/concept-answers.ts';
import type { ConceptPhase } from '../classroom/concept-test/concept-test-plan.ts';
import { conceptTestKey, loadConceptTest, readConceptTestText } from '../classroom/concept-test/concept-test-store.ts';
import type { KeyValueStorage, SaveProblemKind } from '../quest/progress-store.ts';
import type { QuestEngine } from '../quest/quest-engine.ts';
import { conceptTestDue } from './concept-test-due.ts';
import type { PendingWrites } from './pending-writes.ts';
import type { ImportResult, SessionMode } from './quest-session.ts';

/** What the keeper needs of its quest session. */
export interface ConceptTestSession {
  readonly assignment: Assignment | null;
  readonly progressKey: string;
  readonly engine: QuestEngine;
  readonly allPassed: boolean;
  readonly mode: SessionMode;
  readonly saveProblem: SaveProblemKind | null;
  flush(): void;
  start(): SessionMode;
}

/**
 * The assignment's concept test in a quest session (issue 40): the answers so far, which test
 * is due, and handing one in. The answers are written like the survey's (survey-store.ts):
 * through the session's pending writes, so answers that storage refuses stay in memory and
 * are written at the next save; a damaged record is held until it is backed up, and what
 * could be read of it is written in its place.
 */
export class ConceptTestKeeper {
  private answersNow: ConceptTestAnswers;
  private readonly key: string;

  constructor(
    private readonly session: ConceptTestSession,
    private readonly writes: PendingWrites,
    storage: KeyValueStorage,
    wallMs: number,
  ) {
    this.key = conceptTestKey(session.progressKey);
    const loaded = loadConceptTest(storage, session.progressKey, wallMs);
    this.answersNow = loaded.answers;
    if (loaded.damage) writes.replaceDamaged(this.key, loaded.damage, JSON.stringify(loaded.answers));
  }

  get answers(): ConceptTestAnswers {
    return this.answersNow;
  }

  /** The test to take now, if any (concept-test-due.ts); the session's start waits while the one before is due. */
  get due(): ConceptPhase | null {
    const played = this.session.engine.progress.log.events.some((event) => event.type === 'level.opened');
    return conceptTestDue(this.session.assignment, this.answersNow, { played, allPassed: this.session.allPassed });
  }

  /**
   * A test handed in: kept, and written now or at a later save. After the test before, the
   * start that waited for it goes on. Null when written, else why not (yet).
   */
  submit(phase: ConceptPhase, submission: ConceptTestSubmission): SaveProblemKind | null {
    this.answersNow = { ...this.answersNow, [phase]: submission };
    this.writes.put(this.key, JSON.stringify(this.answersNow));
    this.session.flush();
    const problem = this.writes.waiting(this.key) ? (this.session.saveProblem ?? 'storage-blocked') : null;
    if (phase === 'pre' && this.session.mode.kind === 'map') this.session.start();
    return problem;
  }

  /**
   * A backup of a damaged record (the Menu's "Damaged saves"): each test that can be read of
   * it comes back, in place of this visit's answers to the same test (as a survey backup's
   * answers do: survey-keeper.ts); a start that waited for the test before goes on.
   */
  restore(text: string): ImportResult {
    const { answers, lost } = readConceptTestText(text);
    if (answers.pre === null && answers.post === null) return { ok: false, reason: 'unreadable', errors: [] };
    const waited = this.due === 'pre';
    this.answersNow = { pre: answers.pre ?? this.answersNow.pre, post: answers.post ?? this.answersNow.post };
    this.writes.put(this.key, JSON.stringify(this.answersNow));
    this.session.flush();
    if (waited && this.due !== 'pre' && this.session.mode.kind === 'map') this.session.start();
    return { ok: true, repaired: lost };
  }
}
