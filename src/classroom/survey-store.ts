import { writeBackup, type KeyValueStorage } from '../quest/saved-backups.ts';
import { readJson } from '../util/read-json.ts';
import { isRecord } from '../util/is-record.ts';
import type { SurveyAnswers, SurveySubmission } from './survey-answers.ts';

/**
 * A learner's survey answers, kept next to their progress (surveyKey), so an assignment's
 * answers are kept apart from free play's just like its progress, and the exports find them
 * after a reload. The quest session writes them (and keeps them in memory while storage
 * refuses: src/app/pending-writes.ts).
 *
 * A damaged record is never passed over in silence: what can still be read of it
 * is kept (each answer on its own, even from text that is no longer JSON: a record cut short
 * keeps the answers before the cut), what cannot is named, and the exact text is backed up
 * like damaged progress (saved-backups.ts), for the Menu to offer.
 */

/** Where a learner's survey answers are kept: next to their progress, under its key plus `.survey`. */
export function surveyKey(progressKey: string): string {
  return `${progressKey}.survey`;
}

/** A survey record that could not be read as it was. */
export interface SurveyDamage {
  /** The places that could not be read: `survey`, `submittedAt`, `answers` or `answers.<question id>`. */
  lost: string[];
  /** The text was no longer JSON (cut short, a byte changed): which answers were in the damaged part cannot be told. */
  cut: boolean;
  /** The text as it was, for a download. */
  raw: string;
  /** Where it was backed up, or null when there was no room (then it is held: not written over). */
  backupKey: string | null;
}

export type LoadedSurvey = { submission: SurveySubmission | null; damage: SurveyDamage | null };

/** The saved answers under `progressKey`, with what could not be read of them backed up and named. */
export function loadSurvey(storage: KeyValueStorage, progressKey: string, wallMs: number): LoadedSurvey {
  const key = surveyKey(progressKey);
  let raw: string | null;
  try {
    raw = storage.getItem(key);
  } catch {
    return { submission: null, damage: null }; // the progress store reports storage that cannot be read
  }
  if (raw === null) return { submission: null, damage: null };
  const read = readSurveyText(raw);
  if (!read.damaged) return { submission: read.submission, damage: null };
  return { submission: read.submission, damage: { lost: read.lost, cut: read.cut, raw, backupKey: writeBackup(storage, key, raw, wallMs) } };
}

type SurveyRead = { submission: SurveySubmission | null; damaged: boolean; lost: string[]; cut: boolean };

/**
 * What can be read of a saved survey record: the answers are kept when the survey's id and
 * the time it was handed in can be read (an answer is a string or a finite number, as
 * survey-answers.ts gives them); an answer that cannot be read is left out and named. Fields
 * this version does not know are ignored, as in a record of a later one.
 */
export function readSurveyText(raw: string): SurveyRead {
  const json = readJson(raw);
  const fields = json.ok && isRecord(json.value) ? json.value : null;
  const parts = fields ? fieldsOf(fields) : fieldsIn(raw);
  const lost = [...(parts.survey === null ? ['survey'] : []), ...(parts.submittedAt === null ? ['submittedAt'] : []), ...parts.lostAnswers];
  const submission =
    parts.survey !== null && parts.submittedAt !== null ? { survey: parts.survey, submittedAt: parts.submittedAt, answers: parts.answers } : null;
  return { submission, damaged: fields === null || lost.length > 0, lost, cut: fields === null };
}

interface SurveyParts {
  survey: string | null;
  submittedAt: string | null;
  answers: SurveyAnswers;
  lostAnswers: string[];
}

function fieldsOf(fields: Record<string, unknown>): SurveyParts {
  const answers: SurveyAnswers = {};
  const lostAnswers: string[] = [];
  if (isRecord(fields.answers)) {
    for (const [id, answer] of Object.entries(fields.answers)) {
      if (isAnswer(answer)) answers[id] = answer;
      else lostAnswers.push(`answers.${id}`);
    }
  } else {
    lostAnswers.push('answers');
  }
  return { survey: textOf(fields.survey), submittedAt: timeOf(fields.submittedAt), answers, lostAnswers };
}

/**
 * The fields of text that is not JSON (cut short, a byte changed): each string after its name,
 * and every answer after `"answers":{` whose value is complete (a string closed by its quote,
 * a number followed by `,` or `}`: the last digits of a number cut short may be missing).
 */
function fieldsIn(raw: string): SurveyParts {
  const string = (name: string) => {
    const found = new RegExp(`"${name}"\\s*:\\s*("(?:[^"\\\\]|\\\\.)*")`).exec(raw);
    return found ? literal(found[1]!) : null;
  };
  const answers: SurveyAnswers = {};
  const start = /"answers"\s*:\s*\{/.exec(raw);
  if (start) {
    const entry = /\s*("(?:[^"\\]|\\.)*")\s*:\s*("(?:[^"\\]|\\.)*"|-?\d+(?:\.\d+)?(?:[eE][+-]?\d+)?(?=\s*[,}]))\s*,?/y;
    entry.lastIndex = start.index + start[0].length;
    for (let found = entry.exec(raw); found; found = entry.exec(raw)) {
      const id = literal(found[1]!);
      const answer = literal(found[2]!);
      if (typeof id === 'string' && isAnswer(answer)) answers[id] = answer;
    }
  }
  // Which answers were in the damaged part cannot be told (SurveyDamage.cut says so).
  return { survey: textOf(string('survey')), submittedAt: timeOf(string('submittedAt')), answers, lostAnswers: [] };
}

function literal(text: string): unknown {
  const json = readJson(text);
  return json.ok ? json.value : null;
}

function isAnswer(value: unknown): value is string | number {
  return typeof value === 'string' || (typeof value === 'number' && Number.isFinite(value));
}

function textOf(value: unknown): string | null {
  return typeof value === 'string' && value !== '' ? value : null;
}

/** An ISO 8601 time (the exports write it as it is). */
function timeOf(value: unknown): string | null {
  return typeof value === 'string' && !Number.isNaN(Date.parse(value)) ? value : null;
}
