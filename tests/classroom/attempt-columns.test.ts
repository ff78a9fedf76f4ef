import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { ATTEMPT_COLUMNS, ID_COLUMNS, type AttemptOwner } from '../../src/classroom/attempt-columns.ts';
import { attemptRows, csvHeader } from '../../src/classroom/attempt-rows.ts';
import { csvTable, parseCsv } from '../../src/classroom/csv-text.ts';
import { readCsvExport } from '../../src/classroom/dashboard-read-csv.ts';
import type { TaskAttempt } from '../../src/classroom/task-attempts.ts';
import { conceptBankNow, formItems, loadConceptBank } from '../../src/classroom/concept-test/concept-bank.ts';

// The item bank loads apart from the first screen (concept-bank.ts).
await loadConceptBank();

/**
 * The CSV export's one column table (attempt-columns.ts) is where the header, the rows and
 * the dashboard's reader come from. A value written under the wrong name must fail here: a
 * record whose every column holds a value no other column holds is written and read back.
 */

const owner: AttemptOwner = {
  learnerId: 'learner-1',
  attemptId: 'attempt-2',
  installId: 'install-3',
  participant: 'P-4',
  assignment: 'Lesson 5',
  assignmentId: 'a6a6a6a6',
  classCode: 'class-7',
  appVersion: '8.9.10',
  utcOffsetMin: '-330',
  survey: { id: 'default', answers: { ease: 3, 'computer-skill': 'often' } },
  // Two right answers before (the shipped bank's first items of form A), one wrong after.
  conceptTest: {
    pre: {
      form: 'A',
      submittedAt: '',
      answers: Object.fromEntries(
        formItems(conceptBankNow()!, 'A')
          .slice(0, 2)
          .map((item) => [item.id, item.answer]),
      ),
    },
    post: (() => {
      const item = formItems(conceptBankNow()!, 'B')[0]!;
      return { form: 'B', submittedAt: '', answers: { [item.id]: item.choices.find((choice) => choice.id !== item.answer)!.id } };
    })(),
  },
};

const attempts: TaskAttempt[] = [
  {
    level: '01-introduction',
    task: 'orbit',
    mandatory: true,
    kind: 'do',
    startedAt: '2025-03-04T09:00:00.000Z',
    completedAt: '2025-03-04T09:01:00.000Z',
    durationMs: 1001,
    activeMs: 1002,
    how: 'shown',
    points: 1003,
    hintsText: 4,
    hintsGuidance: 5,
    hintsOffered: 6,
    quizAnswers: 7,
    quizCorrect: false,
    quizChoice: null,
    explanationOpens: 8,
    challenge: { renders: 21, changes: 22, rays: 23, scores: [24, 25.5], stars: 3 },
    code: { runs: 31, passed: 32, total: 33, failing: ['sphere-behind', null], solved: true },
  },
  {
    level: '02-shadows',
    task: 'predict',
    mandatory: true,
    kind: 'quiz',
    startedAt: '2025-03-04T09:02:00.000Z',
    completedAt: '2025-03-04T09:03:00.000Z',
    durationMs: 2001,
    activeMs: 2002,
    how: 'done',
    points: 2003,
    hintsText: 14,
    hintsGuidance: 15,
    hintsOffered: 16,
    quizAnswers: 17,
    quizCorrect: true,
    quizChoice: 2,
    explanationOpens: 18,
  },
];

const questions = ['ease', 'computer-skill'];
const text = csvTable(
  csvHeader(questions),
  attemptRows(owner, attempts, questions, (level, task, position) => `${level} ${task} option ${position}`),
  ID_COLUMNS,
);

describe('the CSV column table', () => {
  it('gives every column values no other column has, so the round trip below can tell them apart', () => {
    const parsed = parseCsv(text);
    if (!parsed.ok) throw new Error(parsed.error);
    const [header, ...rows] = parsed.rows;
    const columns = header.map((name, index) => `${name}=${rows.map((row) => row[index]).join('|')}`);
    const values = header.map((_, index) => rows.map((row) => row[index]).join('|'));
    expect(new Set(values).size, columns.join('\n')).toBe(header.length);
  });

  it('reads back every column of a record as it was written', () => {
    const read = readCsvExport('learner.csv', text);
    if (!read.ok) throw new Error(read.reason);
    const { survey, conceptTest, attempts: readAttempts, ...who } = read.record;
    expect(who).toEqual({
      file: 'learner.csv',
      learnerId: owner.learnerId,
      attemptId: owner.attemptId,
      installId: owner.installId,
      participant: owner.participant,
      assignment: owner.assignment,
      assignmentId: owner.assignmentId,
      classCode: owner.classCode,
      appVersion: owner.appVersion,
      utcOffsetMin: owner.utcOffsetMin,
      visits: [],
    });
    // What was asked is read from the survey columns the file has.
    expect(survey).toEqual({ ...owner.survey, asked: { columns: questions } });
    expect(conceptTest).toEqual(owner.conceptTest);
    expect(readAttempts).toEqual(attempts);
  });

  it('writes the columns worked out from others where their names say', () => {
    const parsed = parseCsv(text);
    if (!parsed.ok) throw new Error(parsed.error);
    const [header, ...rows] = parsed.rows;
    const cell = (row: number, name: string) => rows[row][header.indexOf(name)];
    expect([cell(0, 'hints_opened'), cell(1, 'hints_opened')]).toEqual(['9', '29']);
    expect([cell(0, 'shown_by_app'), cell(1, 'shown_by_app')]).toEqual(['true', 'false']);
    expect([cell(0, 'attempts'), cell(1, 'attempts')]).toEqual(['1', '1']);
    // The third option in the level file is "c"; its text comes from the level files.
    expect([cell(0, 'quiz_choice'), cell(1, 'quiz_choice')]).toEqual(['', 'c']);
    expect([cell(0, 'quiz_choice_text'), cell(1, 'quiz_choice_text')]).toEqual(['', '02-shadows predict option 2']);
  });

  it('is what docs/classroom.md lists, in the same order, each with what it holds', () => {
    const docs = readFileSync(new URL('../../docs/classroom.md', import.meta.url), 'utf8');
    const section = docs.slice(docs.indexOf('### CSV: one row per task attempt'));
    const table = section.slice(section.indexOf('| column | what it holds |')).split('\n\n')[0];
    const rows = table
      .split('\n')
      .slice(2)
      .map((line) => /^\| `([^`]+)` \| (.*) \|$/.exec(line));
    expect(
      rows.every((row) => row !== null),
      table,
    ).toBe(true);
    const listed = rows.map((row) => row![1]);
    expect(listed).toEqual([...ATTEMPT_COLUMNS.map((column) => column.name), 'survey_<question>']);
    for (const row of rows) expect(row![2].trim().length, row![1]).toBeGreaterThan(10);
  });
});
