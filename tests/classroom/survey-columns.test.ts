// The class exports' survey columns follow the questions the assignments asked (issue 40):
// a teacher who ticked two questions gets two survey columns, not the whole survey's.
import { describe, expect, it } from 'vitest';
import type { Assignment } from '../../src/classroom/assignment.ts';
import { parseCsv } from '../../src/classroom/csv-text.ts';
import { combinedCsv, readClassFiles, surveyCsv } from '../../src/classroom/dashboard-class.ts';
import { classLearners } from '../../src/classroom/dashboard-learners.ts';
import { exportCsv } from '../../src/classroom/export-csv.ts';
import { buildExport } from '../../src/classroom/export-json.ts';
import { researchCsv } from '../../src/classroom/research-export.ts';
import type { SurveyAnswers } from '../../src/classroom/survey-answers.ts';
import { surveyById } from '../../src/classroom/surveys.ts';
import type { LoggedEvent } from '../../src/quest/event-log.ts';
import { newProgress } from '../../src/quest/progress.ts';
import { CLASS_ASSIGNMENT, simulatedClassFiles, testUuid } from '../support/class-exports.ts';

/** The teacher kept only these two of the default survey's questions. */
const TWO = ['education', 'minutes'];
const choice = Object.fromEntries(surveyById('default')!.questions.map((question) => [question.id, TWO.includes(question.id)]));
const twoQuestions: Assignment = { ...CLASS_ASSIGNMENT, title: 'Two questions', surveyQuestions: choice };

/** A learner of that assignment who answered `answers` (the survey page keeps only asked questions). */
function exportOf(index: number, answers: SurveyAnswers) {
  const startedAt = '2026-03-02T09:00:00.000Z';
  const clock = { monotonicMs: () => 0, wallMs: () => Date.parse(startedAt) };
  const events: LoggedEvent[] = [
    { t: 0, type: 'session.started', at: startedAt },
    { t: 10, type: 'level.opened', level: '01-introduction' },
    { t: 100, type: 'task.shown', level: '01-introduction', task: 'orbit', mandatory: true, required: true },
    { t: 9000, type: 'task.completed', level: '01-introduction', task: 'orbit', mandatory: true, required: true, how: 'done', points: 10 },
  ];
  return {
    progress: { ...newProgress(clock), log: { startedAt, events } },
    participant: `T${index}`,
    installId: '',
    attemptId: testUuid(900 + index),
    assignment: twoQuestions,
    survey: { survey: 'default', submittedAt: '2026-03-02T09:30:00.000Z', answers },
    exportedAt: '2026-03-02T09:31:00.000Z',
    appVersion: '0.1.0',
  };
}

const surveyColumns = (text: string) => {
  const csv = parseCsv(text);
  if (!csv.ok) throw new Error(csv.error);
  return csv.rows[0]!;
};

describe('survey columns of the class exports', () => {
  // One learner left the minutes open: the column stays, since the question was asked.
  const json = { name: 'T1.json', text: JSON.stringify(buildExport(exportOf(1, { education: 'havo', minutes: 35 }))) };
  const csv = { name: 'T2.csv', text: exportCsv(exportOf(2, { education: 'vwo' })) };

  it('reads both files', () => expect(readClassFiles([json, csv]).skipped).toEqual([]));

  it('are the two questions the teacher chose, from a JSON and from a CSV export', () => {
    for (const files of [[json], [csv], [json, csv]]) {
      const learners = classLearners(readClassFiles(files).records);
      expect(surveyColumns(combinedCsv(learners, surveyById)).filter((name) => name.startsWith('survey_'))).toEqual(['survey_education', 'survey_minutes']);
      expect(surveyColumns(surveyCsv(learners, surveyById)).slice(6)).toEqual(TWO);
      expect(surveyColumns(researchCsv(learners, surveyById, { freeText: true })).filter((name) => name.startsWith('survey_'))).toEqual([
        'survey_education',
        'survey_minutes',
      ]);
    }
  });

  it('hold the answers, and an empty cell for the question left open', () => {
    const learners = classLearners(readClassFiles([json, csv]).records);
    const read = parseCsv(surveyCsv(learners, surveyById));
    if (!read.ok) throw new Error(read.error);
    expect(read.rows.slice(1).map((row) => row.slice(1, 2).concat(row.slice(6)))).toEqual([
      ['T1', 'havo', '35'],
      ['T2', 'vwo', ''],
    ]);
  });

  it('are every question of the survey for files that do not say what was asked', () => {
    const learners = classLearners(readClassFiles(simulatedClassFiles(3)).records);
    // The simulated assignment (levels 1 and 2) has no choice: the default asks what fits those levels, and answers keep their columns.
    const columns = surveyColumns(surveyCsv(learners, surveyById)).slice(6);
    expect(columns).toContain('computer-skill');
    expect(columns).toContain('learned-attenuation');
  });
});
