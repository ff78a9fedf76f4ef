import { conceptTestKey } from '../classroom/concept-test/concept-test-store.ts';
import { surveyKey } from '../classroom/survey-store.ts';
import { listBackups, type KeyValueStorage } from '../quest/saved-backups.ts';
import { sessionContextKey } from './session-context.ts';

/**
 * "Withdraw and delete my data" (AVG/GDPR art. 7(3) and 17: consent can be withdrawn, and
 * the data then erased): everything this browser keeps of one assignment, or of free play,
 * is removed. That is the progress with its event log, the session record (participant code
 * and attempt id), the survey's and the concept test's answers, and every backup of these made when one was
 * found damaged. Other assignments, free play's own data and settings stay.
 */

export interface WithdrawReport {
  /** Which of the records were there and are now gone. */
  progress: boolean;
  session: boolean;
  survey: boolean;
  conceptTest: boolean;
  /** How many backups were deleted. */
  backups: number;
  /** Keys the browser refused to delete (blocked storage): the learner is told. */
  failed: string[];
}

export function deleteAssignmentData(storage: KeyValueStorage, progressKey: string): WithdrawReport {
  const records = { progress: progressKey, session: sessionContextKey(progressKey), survey: surveyKey(progressKey), conceptTest: conceptTestKey(progressKey) };
  const report: WithdrawReport = { progress: false, session: false, survey: false, conceptTest: false, backups: 0, failed: [] };
  const remove = (key: string): boolean => {
    try {
      if (storage.getItem(key) === null) return false;
      storage.removeItem(key);
      return true;
    } catch {
      report.failed.push(key);
      return false;
    }
  };
  for (const backup of listBackups(storage, Object.values(records))) if (remove(backup.key)) report.backups += 1;
  report.progress = remove(records.progress);
  report.session = remove(records.session);
  report.survey = remove(records.survey);
  report.conceptTest = remove(records.conceptTest);
  return report;
}
