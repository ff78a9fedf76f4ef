import { describe, expect, it } from 'vitest';
import { readClassFiles, surveyCsv } from '../../src/classroom/dashboard-class.ts';
import { assignmentsOf, classCodesOf, classLearners, filterLearners } from '../../src/classroom/dashboard-learners.ts';
import { summarizeLevels } from '../../src/classroom/dashboard-summary.ts';
import { surveyById } from '../../src/classroom/surveys.ts';
import { parseCsv } from '../../src/classroom/csv-text.ts';
import { exportCsv } from '../../src/classroom/export-csv.ts';
import { buildExport, type QuestExport } from '../../src/classroom/export-json.ts';
import type { ExportInput } from '../../src/classroom/export-context.ts';
import { newProgress } from '../../src/quest/progress.ts';
import { CLASS_ASSIGNMENT, simulatedClassFiles, simulatedExport, testUuid } from '../support/class-exports.ts';

/** The export input that made `file`, with its log cut after `events` events (a file taken earlier). */
function inputOf(file: QuestExport, events = file.events.events.length): ExportInput {
  const log = { startedAt: file.events.startedAt, events: file.events.events.slice(0, events) };
  const clock = { monotonicMs: () => 0, wallMs: () => Date.parse(log.startedAt) };
  return {
    progress: { ...newProgress(clock), log },
    participant: file.participant,
    installId: file.learner.installId,
    attemptId: file.learner.attemptId,
    assignment: CLASS_ASSIGNMENT,
    survey: events === file.events.events.length ? file.survey : null,
    exportedAt: file.exportedAt,
    appVersion: file.appVersion,
  };
}

const json = (input: ExportInput) => `${JSON.stringify(buildExport(input), null, 2)}\n`;

/** The simulation's first learner who passes both levels and answers the survey. */
const student = Array.from({ length: 20 }, (_, index) => simulatedExport(index)).find(
  (file) => file.survey !== null && file.events.events.filter((event) => event.type === 'level.passed').length === 2,
)!;
const all = student.events.events.length;

describe('one learner is one learner', () => {
  // Pressing every button at several moments: midway, after a reload, at the end (JSON and CSV).
  const files = [
    { name: 'midway.json', text: json(inputOf(student, Math.round(all / 3))) },
    { name: 'after-reload.json', text: json(inputOf(student, Math.round((2 * all) / 3))) },
    { name: 'final.json', text: json(inputOf(student)) },
    { name: 'final.csv', text: exportCsv(inputOf(student)) },
  ];

  it('merges four files of one playthrough into one learner who passed, counting nothing twice', () => {
    const { records, skipped } = readClassFiles(files);
    expect(skipped).toEqual([]);
    expect(records).toHaveLength(4);
    const learners = classLearners(records);
    expect(learners).toHaveLength(1);
    expect(learners[0].files).toEqual(['midway.json', 'after-reload.json', 'final.json', 'final.csv']);
    // The final JSON is kept: as complete as the final CSV, and it has the level visits.
    expect(learners[0].parts.map((part) => part.file)).toEqual(['final.json']);
    expect(learners[0].survey?.id).toBe('default');
    const alone = classLearners(readClassFiles([files[2]]).records);
    expect(summarizeLevels(learners)).toEqual(summarizeLevels(alone));
    for (const level of summarizeLevels(learners)) expect(level).toMatchObject({ learners: 1, passed: 1 });
  });

  it('keeps the most complete file whatever the order, a later CSV over an earlier JSON', () => {
    const { records } = readClassFiles([files[3], files[0]]);
    const [learner] = classLearners(records);
    expect(learner.parts.map((part) => part.file)).toEqual(['final.csv']);
    expect(learner.survey?.answers).toEqual(student.survey?.answers);
    for (const level of summarizeLevels([learner])) expect(level).toMatchObject({ learners: 1, passed: 1 });
  });

  it('joins two playthroughs of one code into one learner, and keeps other learners apart', () => {
    const second = { ...inputOf(student), attemptId: testUuid(99) };
    const other = simulatedClassFiles(3).find((file) => !file.name.includes(student.participant!))!;
    const learners = classLearners(readClassFiles([files[2], { name: 'again.json', text: json(second) }, other]).records);
    expect(learners.map((learner) => [learner.learnerId, learner.parts.length])).toEqual([
      [student.participant, 2],
      [other.name.replace(/^ray-tracer-quest-|\.json$/g, ''), 1],
    ]);
    expect(learners[0].attempts).toHaveLength(2 * readClassFiles([files[2]]).records[0].attempts.length);
  });

  it('merges old files without ids by participant and log start', () => {
    const strip = (text: string) => {
      const { learner: _learner, ...old } = JSON.parse(text) as QuestExport;
      return JSON.stringify(old);
    };
    const read = readClassFiles([files[0], files[2]].map((file) => ({ ...file, text: strip(file.text) })));
    expect(read.skipped).toEqual([]);
    const learners = classLearners(read.records);
    expect(learners).toHaveLength(1);
    expect(learners[0].parts.map((part) => part.file)).toEqual(['final.json']);
  });
});

describe('filters and the survey CSV', () => {
  const inClass = (code: string, index: number) => {
    const file = simulatedExport(index);
    const input = { ...inputOf(file), assignment: { ...CLASS_ASSIGNMENT, classCode: code } };
    return { name: `${code}-${index}.json`, text: json(input) };
  };
  const records = readClassFiles([inClass('3A', 0), inClass('3A', 1), inClass('3B', 2), ...simulatedClassFiles(4).slice(3)]).records;
  const learners = classLearners(records);

  it('lists the assignments and class codes, and shows one of them', () => {
    // A class code is part of the assignment: 3A, 3B and no code are three assignments.
    expect(
      assignmentsOf(learners)
        .map((assignment) => assignment.learners)
        .sort(),
    ).toEqual([1, 1, 2]);
    expect(classCodesOf(learners)).toEqual(['', '3A', '3B']);
    expect(filterLearners(learners, { assignmentId: null, classCode: '3A' }).map((learner) => learner.participant)).toEqual(['P01', 'P02']);
    const threeB = learners.find((learner) => learner.classCode === '3B')!;
    expect(filterLearners(learners, { assignmentId: threeB.assignmentId, classCode: null })).toEqual([threeB]);
  });

  it('writes one survey row per learner who answered, one column per question, codes quoted', () => {
    const text = surveyCsv(learners, surveyById);
    const csv = parseCsv(text);
    if (!csv.ok) throw new Error(csv.error);
    const [header, ...rows] = csv.rows;
    expect(header.slice(0, 6)).toEqual(['learner_id', 'participant', 'assignment', 'assignment_id', 'class_code', 'survey']);
    expect(header).toContain('computer-skill');
    const answered = learners.filter((learner) => learner.survey);
    expect(rows).toHaveLength(answered.length);
    const first = Object.fromEntries(header.map((name, index) => [name, rows[0][index]]));
    expect(first['computer-skill']).toBe(String(answered[0].survey?.answers['computer-skill']));
    expect(text).toContain('"P01","P01"');
  });
});
