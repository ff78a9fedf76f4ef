import type { SurveySubmission } from '../classroom/survey-answers.ts';
import { loadSurvey, readSurveyText, surveyKey, type SurveyDamage } from '../classroom/survey-store.ts';
import type { KeyValueStorage, SaveProblemKind } from '../quest/progress-store.ts';
import type { PendingWrites } from './pending-writes.ts';
import type { ImportResult } from './quest-session.ts';

/** What the keeper needs of its quest session. */
export interface SurveySession {
  readonly progressKey: string;
  /** Saves the progress and every write that waits; why a write failed, or null. */
  save(): SaveProblemKind | null;
  /** Tells the session's listeners (the UI) that something changed. */
  notify(): void;
}

/**
 * The closing survey in a quest session: the answers handed in, and a damaged record of them.
 * The answers are written through the session's pending writes (survey-store.ts), so answers
 * that storage refuses stay in memory and are written at the next save; a damaged record is
 * backed up, or held until it can be, and what could be read of it is written in its place.
 */
export class SurveyKeeper {
  /** What of the saved answers could not be read when the session started, if any. */
  readonly damage: SurveyDamage | null;
  private submissionNow: SurveySubmission | null;
  private readonly key: string;

  constructor(
    private readonly session: SurveySession,
    private readonly writes: PendingWrites,
    storage: KeyValueStorage,
    wallMs: number,
  ) {
    this.key = surveyKey(session.progressKey);
    const loaded = loadSurvey(storage, session.progressKey, wallMs);
    this.submissionNow = loaded.submission;
    this.damage = loaded.damage;
    if (loaded.damage) writes.replaceDamaged(this.key, loaded.damage, this.submissionNow && JSON.stringify(this.submissionNow));
  }

  /** The answers, once handed in (kept in memory when they could not be written yet). */
  get submission(): SurveySubmission | null {
    return this.submissionNow;
  }

  /** Answers handed in: kept, and written now or at a later save. Null when written, else why not (yet). */
  submit(answers: SurveySubmission): SaveProblemKind | null {
    this.submissionNow = answers;
    this.writes.put(this.key, JSON.stringify(answers));
    const problem = this.session.save();
    this.session.notify();
    return this.writes.waiting(this.key) ? (problem ?? 'storage-blocked') : null;
  }

  /**
   * A survey backup: the answers that can be read of it come back (they replace this visit's
   * answers to the same questions, the other answers stay), with the time they were handed in.
   */
  restore(text: string): ImportResult {
    const { submission, lost } = readSurveyText(text);
    if (submission === null) return { ok: false, reason: 'unreadable', errors: [] };
    const current = this.submissionNow?.survey === submission.survey ? this.submissionNow.answers : {};
    this.submit({ ...submission, answers: { ...current, ...submission.answers } });
    return { ok: true, repaired: lost };
  }
}
