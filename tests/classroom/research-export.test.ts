import { describe, expect, it } from 'vitest';
import { combinedCsv, readClassFiles } from '../../src/classroom/dashboard-class.ts';
import { parseCsv } from '../../src/classroom/csv-text.ts';
import { classLearners } from '../../src/classroom/dashboard-learners.ts';
import { researchCsv } from '../../src/classroom/research-export.ts';
import { surveyById } from '../../src/classroom/surveys.ts';
import { simulatedClassFiles } from '../support/class-exports.ts';

function table(text: string): Record<string, string>[] {
  const read = parseCsv(text);
  if (!read.ok) throw new Error(read.error);
  const [header, ...rows] = read.rows;
  return rows.map((row) => Object.fromEntries(header.map((name, index) => [name, row[index]])));
}

const learners = classLearners(readClassFiles(simulatedClassFiles(12)).records);
const combined = table(combinedCsv(learners, surveyById));

describe('research export', () => {
  const text = researchCsv(learners, surveyById, { freeText: false });
  const rows = table(text);

  it('has no wall-clock time, device id or file name anywhere', () => {
    expect(text).not.toMatch(/\d{4}-\d\d-\d\dT\d\d:\d\d/);
    const header = Object.keys(rows[0]);
    for (const name of ['install_id', 'file', 'started_at', 'completed_at']) expect(header).not.toContain(name);
    expect(header).toContain('started_s');
    expect(header).toContain('completed_s');
  });

  it('keeps every row, with times in seconds since the learner’s first task', () => {
    expect(rows).toHaveLength(combined.length);
    rows.forEach((row, index) => {
      const original = combined[index];
      expect(row.learner_id).toBe(original.learner_id);
      expect(row.task).toBe(original.task);
      expect(row.active_ms).toBe(original.active_ms);
      const first = Math.min(...combined.filter((other) => other.learner_id === original.learner_id).map((other) => Date.parse(other.started_at)));
      expect(Number(row.started_s)).toBeCloseTo((Date.parse(original.started_at) - first) / 1000, 1);
      if (original.completed_at === '') expect(row.completed_s).toBe('');
      else expect(Number(row.completed_s)).toBeCloseTo((Date.parse(original.completed_at) - first) / 1000, 1);
    });
    // Each learner's first task starts at 0.
    for (const learner of new Set(rows.map((row) => row.learner_id))) {
      expect(Math.min(...rows.filter((row) => row.learner_id === learner).map((row) => Number(row.started_s)))).toBe(0);
    }
  });

  it('leaves free text out unless asked, and then marks its columns', () => {
    expect(Object.keys(rows[0])).toContain('survey_computer-skill');
    expect(Object.keys(rows[0]).some((name) => name.startsWith('survey_feedback'))).toBe(false);
    expect(text).not.toContain('More levels please');
    const withText = table(researchCsv(learners, surveyById, { freeText: true }));
    expect(Object.keys(withText[0])).toContain('survey_feedback_free_text');
    expect(Object.keys(withText[0])).toContain('survey_computer-skill');
    expect(withText.some((row) => row.survey_feedback_free_text.startsWith('More levels please'))).toBe(true);
  });
});
