import type { KeyValueStorage } from '../quest/progress-store.ts';
import { readJson } from '../util/read-json.ts';
import { isRecord } from '../util/is-record.ts';
import type { SurveySubmission } from './survey-answers.ts';

/** Where a learner's survey answers are kept: next to their progress, under its key plus `.survey`. */
export function surveyKey(progressKey: string): string {
  return `${progressKey}.survey`;
}

/**
 * Reads a learner's survey answers, kept next to their progress (surveyKey), so an
 * assignment's answers are kept apart from free play's just like its progress, and the
 * exports find them after a reload. The quest session writes them (and keeps them in memory
 * while storage refuses: src/app/pending-writes.ts).
 */
export class SurveyStore {
  private readonly key: string;

  /** `progressKey`: PROGRESS_KEY, or assignmentProgressKey(assignment). */
  constructor(
    private readonly storage: KeyValueStorage,
    progressKey: string,
  ) {
    this.key = surveyKey(progressKey);
  }

  /** The saved submission, or null when there is none or it cannot be read. */
  load(): SurveySubmission | null {
    let value: unknown;
    try {
      const json = readJson(this.storage.getItem(this.key) ?? 'null');
      value = json.ok ? json.value : null;
    } catch {
      return null;
    }
    if (!isRecord(value) || typeof value.survey !== 'string' || typeof value.submittedAt !== 'string' || !isRecord(value.answers)) return null;
    const answers: SurveySubmission['answers'] = {};
    for (const [id, answer] of Object.entries(value.answers)) if (typeof answer === 'string' || typeof answer === 'number') answers[id] = answer;
    return { survey: value.survey, submittedAt: value.submittedAt, answers };
  }
}
