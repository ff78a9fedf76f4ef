import { msg, str } from '@lit/localize';
import { z } from 'zod';
import { eventLogSchema } from '../quest/event-log.ts';
import { describeIssue, issuesOf } from '../scene/scene-issues.ts';
import { PROGRESS_KIND } from '../quest/progress.ts';
import { isRecord } from '../util/is-record.ts';
import type { Issue } from '../util/issue.ts';
import { readJson } from '../util/read-json.ts';
import { readLog } from './task-attempts.ts';
import { learnerKey, normalParticipantCode } from './participant-code.ts';
import { EXPORT_FORMAT, EXPORT_VERSION } from './export-json.ts';
import type { ClassRecord, FileRead } from './dashboard-record.ts';
import type { SurveyAnswers } from './survey-answers.ts';
import type { SurveyAsked } from './survey-columns.ts';
import { readConceptTestValue } from './concept-test/concept-test-store.ts';

/**
 * Reads a learner's JSON export (src/classroom/export-json.ts) for the dashboard. The
 * event log is checked strictly, since every number on the dashboard comes from it; the
 * rest is read leniently so that a field added to exports later does not make a class's
 * files unreadable.
 */

const exportSchema = z.looseObject({
  format: z.literal(EXPORT_FORMAT),
  version: z.literal(EXPORT_VERSION),
  participant: z.string().nullish(),
  learner: z.unknown().optional(),
  assignment: z.unknown(),
  events: z.unknown(),
  survey: z.unknown(),
});

export function readJsonExport(file: string, text: string): FileRead {
  const json = readJson(text);
  if (!json.ok) return { ok: false, file, reason: msg('the file is damaged'), detail: json.issue };
  const value = json.value;
  if (isXapi(value))
    return {
      ok: false,
      file,
      reason: msg("xAPI statements, which are for a school's learning record store: drop the student's JSON or CSV export here instead"),
    };
  if (!isRecord(value)) return { ok: false, file, reason: msg('not a Ray Tracer Quest export (the file holds no JSON object)') };
  if (value.kind === PROGRESS_KIND) return { ok: false, file, reason: msg('a saved progress file, not an export: export the results from the game instead') };
  if (value.format !== EXPORT_FORMAT) return { ok: false, file, reason: msg('not a Ray Tracer Quest export (no "format": "ray-tracer-quest-export")') };
  if (typeof value.version === 'number' && value.version > EXPORT_VERSION) {
    return { ok: false, file, reason: msg(str`made by a newer version of the app (export version ${value.version}); open the dashboard of that version`) };
  }
  const parsed = exportSchema.safeParse(value, { error: describeIssue });
  if (!parsed.success) return { ok: false, file, reason: msg('damaged export'), detail: issuesOf(parsed.error.issues)[0] };
  const log = eventLogSchema.safeParse(parsed.data.events, { error: describeIssue });
  if (!log.success) return { ok: false, file, reason: msg('damaged event log'), detail: inEvents(issuesOf(log.error.issues)[0]) };
  const { attempts, visits } = readLog(log.data);
  // `5h2-03` and `5H2-03` are one learner (participant-code.ts).
  const participant = normalParticipantCode(parsed.data.participant ?? '');
  const assignment = assignmentOf(parsed.data.assignment);
  const learner = (name: string) => (isRecord(parsed.data.learner) && typeof parsed.data.learner[name] === 'string' ? parsed.data.learner[name] : '');
  return {
    ok: true,
    record: {
      file,
      participant,
      learnerId: learnerKey(learner('id') || participant, participant) || `file:${file}`,
      // An older export's log is still one playthrough: its start time tells it apart.
      attemptId: learner('attemptId') || `log:${assignment.assignmentId}:${participant}:${log.data.startedAt}`,
      installId: learner('installId'),
      appVersion: typeof value.appVersion === 'string' ? value.appVersion : '',
      utcOffsetMin: typeof value.utcOffsetMin === 'number' ? String(value.utcOffsetMin) : '',
      ...assignment,
      attempts,
      visits,
      survey: readSurvey(parsed.data.survey, parsed.data.assignment),
      // Only what can be read of it: a damaged answer is left out (as when the game loads it).
      conceptTest: isRecord(value.conceptTest) ? readConceptTestValue(value.conceptTest).answers : null,
    },
  };
}

/** A list of statements (or one) with an actor and a verb, as the xAPI download writes them. */
function isXapi(value: unknown): boolean {
  const first = Array.isArray(value) ? value[0] : value;
  return isRecord(first) && isRecord(first.actor) && isRecord(first.verb);
}

function assignmentOf(assignment: unknown): { assignment: string; assignmentId: string; classCode: string } {
  const field = (name: string) => (isRecord(assignment) && typeof assignment[name] === 'string' ? assignment[name] : '');
  return { assignment: field('title'), assignmentId: field('id'), classCode: field('classCode') };
}

/**
 * The survey submission (survey-answers.ts SurveySubmission): its id and the answers that are
 * numbers or text, and what the assignment asked (its levels and the teacher's choice).
 */
function readSurvey(survey: unknown, assignment: unknown): ClassRecord['survey'] {
  if (!isRecord(survey) || typeof survey.survey !== 'string' || !isRecord(survey.answers)) return null;
  const answers = Object.fromEntries(Object.entries(survey.answers).filter(([, value]) => typeof value === 'number' || typeof value === 'string'));
  return { id: survey.survey, answers: answers as SurveyAnswers, asked: askedOf(assignment) };
}

function askedOf(assignment: unknown): SurveyAsked {
  if (!isRecord(assignment) || !Array.isArray(assignment.levels)) return null;
  const levels = assignment.levels.filter((level): level is string => typeof level === 'string');
  const choice = isRecord(assignment.surveyQuestions)
    ? Object.fromEntries(Object.entries(assignment.surveyQuestions).filter((entry): entry is [string, boolean] => typeof entry[1] === 'boolean'))
    : undefined;
  return choice ? { levels, choice } : { levels };
}

/** An issue of the event log, at its place in the export file. */
function inEvents(issue: Issue | undefined): Issue | undefined {
  return issue && { ...issue, path: issue.path === '(root)' || issue.path === null ? 'events' : `events.${issue.path}` };
}
