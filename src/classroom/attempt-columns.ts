import { HOW_COMPLETED } from '../quest/event-log.ts';
import { TASK_KINDS, type TaskKind } from '../quest/goal.ts';
import { optionId, optionPosition, type OptionText } from './quiz-options.ts';
import type { SurveyAnswers } from './survey-answers.ts';
import type { ConceptTestAnswers } from './concept-test/concept-answers.ts';
import { CONCEPT_COLUMNS } from './concept-test/concept-columns.ts';
import { CHALLENGE_COLUMNS } from './challenge-columns.ts';
import { CODE_LAB_COLUMNS } from './code-lab-columns.ts';
import { hintsOpened, type TaskAttempt } from './task-attempts.ts';

/**
 * The CSV export's columns, each once: its name, the cell a row gets, and how the dashboard
 * reads that cell back. The header, the row writer (attempt-rows.ts) and the reader
 * (dashboard-read-csv.ts) all come from this one table, so a value cannot drift into
 * another column's place; docs/classroom.md says what each holds (a test checks it lists
 * exactly these, in this order).
 */

export type CsvCell = string | number | boolean;

/** Who the attempts belong to: '' for no participant code, no assignment, no class code. */
export interface AttemptOwner {
  learnerId: string;
  attemptId: string;
  installId: string;
  participant: string;
  assignment: string;
  assignmentId: string;
  classCode: string;
  /** The version of the app that wrote the file (package.json), '' when the file does not say. */
  appVersion: string;
  /** Minutes the device's clock was ahead of UTC when the file was made (120 in Dutch summer time), '' when unknown. */
  utcOffsetMin: string;
  survey: { id: string; answers: SurveyAnswers } | null;
  /** The concept test's answers, when the assignment had one (concept-columns.ts). */
  conceptTest?: ConceptTestAnswers | null;
}

/** What one row is written from: whose it is, the attempt, and the attempt's number for its task (1, 2, …). */
export interface AttemptRow {
  owner: AttemptOwner;
  attempt: TaskAttempt;
  number: number;
  /** The text of a chosen quiz option, from the level files in the file's language. */
  optionText: OptionText;
}

/** The owner's fields a row carries as they are (the survey's answers have columns of their own). */
type OwnerText = Exclude<keyof AttemptOwner, 'survey' | 'conceptTest'>;

/** What the reader gathers from one row's cells; `how` is settled afterwards from `completedAt` and `shownByApp`. */
export interface ReadRow {
  owner: Record<OwnerText, string> & { surveyId: string; conceptTest: ConceptTestAnswers };
  attempt: TaskAttempt;
  shownByApp: boolean;
}

/** Why a cell cannot be read: a count must be a number of at least 0, a time a date. */
export type CellProblem = 'not-a-count' | 'not-a-date';

export interface AttemptColumn {
  name: string;
  /** An identifier: always written in quotes, so a reader told to keep quoted fields as text keeps "007". */
  quoted: boolean;
  /** A file without it is not a Ray Tracer Quest CSV export; the others may be missing in older files (read as empty). */
  required: boolean;
  value(row: AttemptRow): CsvCell;
  /** Puts the cell where it belongs; absent for a column worked out from others (`hints_opened`, `attempts`, `quiz_choice_text`). */
  read?(cell: string, into: ReadRow): CellProblem | void;
}

/** A count or a time in milliseconds; an empty cell is 0. */
type CountField = 'durationMs' | 'activeMs' | 'points' | 'hintsText' | 'hintsGuidance' | 'hintsOffered' | 'quizAnswers' | 'explanationOpens';

const plain = { quoted: false, required: false };

function ownerColumn(name: string, field: OwnerText, quoted: boolean, required = false): AttemptColumn {
  return { name, quoted, required, value: ({ owner }) => owner[field], read: (cell, into) => void (into.owner[field] = cell) };
}

function countColumn(name: string, field: CountField, required = false): AttemptColumn {
  return {
    name,
    quoted: false,
    required,
    value: ({ attempt }) => attempt[field],
    read: (cell, into) => {
      const count = cell === '' ? 0 : Number(cell);
      if (!Number.isFinite(count) || count < 0) return 'not-a-count';
      into.attempt[field] = count;
    },
  };
}

export const ATTEMPT_COLUMNS: readonly AttemptColumn[] = [
  ownerColumn('learner_id', 'learnerId', true),
  ownerColumn('attempt_id', 'attemptId', true),
  ownerColumn('install_id', 'installId', true),
  ownerColumn('participant', 'participant', true, true),
  ownerColumn('assignment', 'assignment', false),
  ownerColumn('assignment_id', 'assignmentId', true),
  ownerColumn('class_code', 'classCode', true),
  { name: 'level', quoted: false, required: true, value: ({ attempt }) => attempt.level, read: (cell, into) => void (into.attempt.level = cell) },
  { name: 'task', quoted: false, required: true, value: ({ attempt }) => attempt.task, read: (cell, into) => void (into.attempt.task = cell) },
  {
    name: 'kind',
    ...plain,
    value: ({ attempt }) => attempt.kind ?? '',
    read: (cell, into) => void (into.attempt.kind = TASK_KINDS.find((kind): kind is TaskKind => kind === cell) ?? null),
  },
  { name: 'mandatory', ...plain, value: ({ attempt }) => attempt.mandatory, read: (cell, into) => void (into.attempt.mandatory = cell === 'true') },
  {
    name: 'started_at',
    quoted: false,
    required: true,
    value: ({ attempt }) => attempt.startedAt,
    read: (cell, into) => {
      if (Number.isNaN(Date.parse(cell))) return 'not-a-date';
      into.attempt.startedAt = cell;
    },
  },
  {
    name: 'completed_at',
    ...plain,
    value: ({ attempt }) => attempt.completedAt ?? '',
    read: (cell, into) => void (into.attempt.completedAt = cell === '' ? null : cell),
  },
  countColumn('duration_ms', 'durationMs', true),
  countColumn('active_ms', 'activeMs', true),
  {
    name: 'how',
    ...plain,
    value: ({ attempt }) => attempt.how ?? '',
    read: (cell, into) => void (into.attempt.how = HOW_COMPLETED.find((how) => how === cell) ?? null),
  },
  countColumn('hints_text', 'hintsText'),
  countColumn('hints_guidance', 'hintsGuidance'),
  countColumn('hints_offered', 'hintsOffered'),
  { name: 'hints_opened', ...plain, value: ({ attempt }) => hintsOpened(attempt) },
  { name: 'shown_by_app', ...plain, value: ({ attempt }) => attempt.how === 'shown', read: (cell, into) => void (into.shownByApp = cell === 'true') },
  { name: 'attempts', ...plain, value: ({ number }) => number },
  countColumn('quiz_answers', 'quizAnswers'),
  {
    name: 'quiz_correct',
    ...plain,
    value: ({ attempt }) => attempt.quizCorrect ?? '',
    read: (cell, into) => void (into.attempt.quizCorrect = cell === '' ? null : cell === 'true'),
  },
  {
    name: 'quiz_choice',
    ...plain,
    value: ({ attempt }) => (attempt.quizChoice === null ? '' : optionId(attempt.quizChoice)),
    read: (cell, into) => void (into.attempt.quizChoice = optionPosition(cell.trim().toLowerCase())),
  },
  {
    name: 'quiz_choice_text',
    ...plain,
    value: ({ attempt, optionText }) => (attempt.quizChoice === null ? '' : optionText(attempt.level, attempt.task, attempt.quizChoice)),
  },
  countColumn('explanation_opens', 'explanationOpens'),
  countColumn('points', 'points'),
  ...CHALLENGE_COLUMNS,
  ...CODE_LAB_COLUMNS,
  ownerColumn('app_version', 'appVersion', false),
  {
    // A number, not text: a text cell starting with "-" would get the apostrophe that keeps formulas out (csv-text.ts).
    name: 'utc_offset_min',
    ...plain,
    value: ({ owner }) => (owner.utcOffsetMin === '' ? '' : Number(owner.utcOffsetMin)),
    read: (cell, into) => void (into.owner.utcOffsetMin = cell.trim()),
  },
  { name: 'survey', ...plain, value: ({ owner }) => owner.survey?.id ?? '', read: (cell, into) => void (into.owner.surveyId = cell) },
  ...CONCEPT_COLUMNS,
];

/** The survey's answers follow the table as one `survey_<question>` column per question. */
export const SURVEY_PREFIX = 'survey_';

/** Identifiers, always written in quotes (see `AttemptColumn.quoted`). */
export const ID_COLUMNS: ReadonlySet<string> = new Set(ATTEMPT_COLUMNS.filter((column) => column.quoted).map((column) => column.name));

/** What the reader starts a row from: every cell empty. */
export function emptyReadRow(): ReadRow {
  return {
    owner: {
      learnerId: '',
      attemptId: '',
      installId: '',
      participant: '',
      assignment: '',
      assignmentId: '',
      classCode: '',
      appVersion: '',
      utcOffsetMin: '',
      surveyId: '',
      conceptTest: { pre: null, post: null },
    },
    attempt: {
      level: '',
      task: '',
      mandatory: false,
      kind: null,
      startedAt: '',
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
    },
    shownByApp: false,
  };
}
