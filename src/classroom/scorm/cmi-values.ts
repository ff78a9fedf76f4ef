import { isoDuration } from '../iso-duration.ts';
import type { ScormVersion } from './lms-api.ts';
import type { LmsInteraction, LmsReport } from './lms-report.ts';

/**
 * The report (lms-report.ts) as the data model element values of each SCORM version: pairs
 * of element and value, in the order they are set. Pure, so that the tests read exactly
 * what a platform receives.
 *
 * SCORM 2004 4th edition (RTE 4th ed. §4.2): completion and success apart, the score raw,
 * min, max and scaled (raw / max, −1…1), interactions with their type, learner response,
 * result, timestamp and latency as ISO 8601.
 *
 * SCORM 1.2 (RTE 1.2 §3.4): one lesson status (`passed` when done, else `incomplete`);
 * a score that must lie between 0 and 100 (CMIDecimal, §3.4.2.2.2), so the points are
 * given as a percentage of the maximum; interactions as a journal with 1.2's vocabulary:
 * a choice is a single letter (a–z: CMIFeedback for `choice`), a task done in the lab is a
 * `performance`, a wrong answer is `wrong`, times are HH:MM:SS and latencies HHHH:MM:SS.SS.
 */

export type CmiValue = readonly [element: string, value: string];

/** The status, the score and where the learner is. */
export function statusValues(version: ScormVersion, report: LmsReport, location: string | null): CmiValue[] {
  const { raw, max } = report.score;
  if (version === '2004') {
    return [
      ['cmi.completion_status', report.completed ? 'completed' : 'incomplete'],
      ['cmi.success_status', report.completed ? 'passed' : 'unknown'],
      ['cmi.score.min', '0'],
      ['cmi.score.max', String(max)],
      ['cmi.score.raw', String(raw)],
      ['cmi.score.scaled', String(max > 0 ? round(raw / max, 4) : 0)],
      ...(location === null ? [] : ([['cmi.location', location]] as const)),
    ];
  }
  return [
    ['cmi.core.lesson_status', report.completed ? 'passed' : 'incomplete'],
    ['cmi.core.score.min', '0'],
    ['cmi.core.score.max', '100'],
    ['cmi.core.score.raw', String(max > 0 ? round((100 * raw) / max, 2) : 0)],
    ...(location === null ? [] : ([['cmi.core.lesson_location', location]] as const)),
  ];
}

/** One interaction at position `index` of the platform's list. */
export function interactionValues(version: ScormVersion, index: number, interaction: LmsInteraction): CmiValue[] {
  const at = `cmi.interactions.${index}`;
  if (version === '2004') {
    return [
      [`${at}.id`, interaction.id],
      [`${at}.type`, interaction.type],
      [`${at}.timestamp`, interaction.timestamp.replace(/(\.\d\d)\d*Z$/, '$1Z')],
      [`${at}.learner_response`, interaction.response],
      [`${at}.result`, interaction.result],
      [`${at}.latency`, isoDuration(interaction.latencyMs)],
    ];
  }
  return [
    [`${at}.id`, interaction.id],
    [`${at}.type`, interaction.type === 'other' ? 'performance' : interaction.type],
    [`${at}.time`, interaction.timestamp.slice(11, 19)],
    [`${at}.student_response`, interaction.response],
    [`${at}.result`, interaction.result === 'incorrect' ? 'wrong' : interaction.result],
    [`${at}.latency`, timespan12(interaction.latencyMs)],
  ];
}

/**
 * This launch's time, and the exit: always `suspend`, also once the assignment is done, so
 * that the next launch resumes with the progress (cmi.entry `resume`, the suspend data)
 * instead of starting a new attempt that would report the finished assignment as
 * incomplete (RTE 4th ed. §4.2.10; RTE 1.2 §3.4.4 cmi.core.exit).
 */
export function exitValues(version: ScormVersion, sessionMs: number): CmiValue[] {
  if (version === '2004') {
    return [
      ['cmi.session_time', isoDuration(sessionMs)],
      ['cmi.exit', 'suspend'],
    ];
  }
  return [
    ['cmi.core.session_time', timespan12(sessionMs)],
    ['cmi.core.exit', 'suspend'],
  ];
}

/** The elements that differ in name only: `resume` when this launch continues an earlier one, and who the learner is. */
export function elementsOf(version: ScormVersion): { entry: string; learnerId: string } {
  return version === '2004' ? { entry: 'cmi.entry', learnerId: 'cmi.learner_id' } : { entry: 'cmi.core.entry', learnerId: 'cmi.core.student_id' };
}

/** SCORM 1.2's CMITimespan, HHHH:MM:SS.SS (RTE 1.2 §3.4.2, data types). */
export function timespan12(ms: number): string {
  const hundredths = Math.round(ms / 10);
  const hours = Math.floor(hundredths / 360_000);
  const minutes = Math.floor((hundredths % 360_000) / 6_000);
  const seconds = (hundredths % 6_000) / 100;
  return `${String(hours).padStart(4, '0')}:${String(minutes).padStart(2, '0')}:${seconds.toFixed(2).padStart(5, '0')}`;
}

function round(value: number, digits: number): number {
  const scale = 10 ** digits;
  return Math.round(value * scale) / scale;
}
