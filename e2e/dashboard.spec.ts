import { expect, test } from '@playwright/test';
import { readFileSync } from 'node:fs';
import { readFile } from 'node:fs/promises';
import { parseCsv } from '../src/classroom/csv-text.ts';
import { readClassFiles } from '../src/classroom/dashboard-class.ts';
import { summarizeLevels } from '../src/classroom/dashboard-summary.ts';
import { summarizeSurveys } from '../src/classroom/dashboard-survey.ts';
import { parseSurvey } from '../src/classroom/survey-schema.ts';
import { simulatedClassFiles } from '../tests/support/class-exports.ts';

// A teacher's afternoon: 30 learners' exports (20 chosen with the file button, 10 dropped on
// the page) plus one damaged file; the charts show the class, the damaged file is listed with
// its reason, and the combined CSV has every attempt.

const files = simulatedClassFiles(30);
const damaged = { name: 'P31-truncated.json', text: files[0].text.slice(0, 300) };
const expected = readClassFiles(files);
const levels = summarizeLevels(expected.records);
// Node's loader wants an import attribute for JSON that vite does not: the survey is read as a file.
const defaultSurvey = parseSurvey(JSON.parse(readFileSync('src/classroom/surveys/default.survey.json', 'utf8')));
const surveyById = () => (defaultSurvey.ok ? defaultSurvey.survey : undefined);

test('the dashboard reads a class of exports, shows the charts and skips a damaged file', async ({ page }) => {
  const errors: string[] = [];
  page.on('pageerror', (error) => errors.push(error.message));
  await page.goto('./#/dashboard');
  const dashboard = page.locator('rt-dashboard-page');
  await expect(dashboard.getByText('Nothing is uploaded')).toBeVisible();
  await expect(dashboard.getByRole('button', { name: 'Download combined CSV' })).toBeDisabled();

  // The file button (keyboard and touch path).
  await dashboard
    .locator('input[type=file]')
    .setInputFiles([...files.slice(0, 20), damaged].map((file) => ({ name: file.name, mimeType: 'application/json', buffer: Buffer.from(file.text) })));
  await expect(dashboard.getByRole('status').filter({ hasText: '20 students counted, 1 file skipped.' })).toBeVisible();

  // Drag and drop, added to what was read.
  const dataTransfer = await page.evaluateHandle((dropped) => {
    const transfer = new DataTransfer();
    for (const file of dropped) transfer.items.add(new File([file.text], file.name, { type: 'application/json' }));
    return transfer;
  }, files.slice(20));
  await dashboard.locator('.drop').dispatchEvent('drop', { dataTransfer });
  await expect(dashboard.getByRole('status').filter({ hasText: '30 students counted, 1 file skipped.' })).toBeVisible();

  // The skipped file and its reason.
  const skipped = dashboard.locator('.skipped-files');
  await expect(skipped.getByRole('row', { name: /P31-truncated\.json/ })).toContainText('not valid JSON at line');

  // One section per level; per task a row of dots (one per learner who completed it) and a completion bar.
  for (const level of levels) {
    const section = dashboard.locator(`section.level[data-level="${level.level}"]`);
    await expect(section).toBeVisible();
    const rows = section.locator('rt-dashboard-times svg.row');
    await expect(rows).toHaveCount(level.tasks.length + 1);
    for (const [index, task] of level.tasks.entries()) {
      await expect(rows.nth(index).locator('circle.dot')).toHaveCount(task.times.length);
      await expect(rows.nth(index).locator('rect.box')).toHaveCount(task.stats ? 1 : 0);
    }
    await expect(rows.last().locator('circle.dot')).toHaveCount(level.passed);
    await expect(section.locator('rt-dashboard-completion svg.bar')).toHaveCount(level.tasks.length);
    await expect(section.locator('rt-dashboard-stuck tbody tr')).toHaveCount(level.tasks.length);
  }
  expect(levels[0].learners).toBe(30);

  // The survey: six 1–5 questions in one Likert chart whose segments add up to the answers.
  const respondents = expected.records.filter((record) => record.survey).length;
  const survey = dashboard.locator('section.survey');
  await expect(survey).toContainText(`${respondents} students answered.`);
  const helped = survey.locator('rt-dashboard-likert').filter({ hasText: 'Helped a lot' });
  await expect(helped.locator('svg.bar')).toHaveCount(6);
  const shadows = helped.locator('svg.bar[data-question="learned-soft-shadows"]');
  const scale = summarizeSurveys(expected.records, surveyById).surveys[0].scales.find((item) => item.id === 'learned-soft-shadows')!;
  await expect(shadows.locator('rect.segment')).toHaveCount(scale.counts.filter((count) => count > 0).length);
  await expect(shadows).toHaveAttribute('aria-label', new RegExp(`1 – Did not help: ${scale.counts[0]} .*5 – Helped a lot: ${scale.counts[4]} `));
  await expect(helped.locator('.legend li')).toHaveCount(5);
  await expect(helped.locator('.legend')).toContainText('1 – Did not help');

  // The combined CSV: one row per attempt of every learner.
  const downloading = page.waitForEvent('download');
  await dashboard.getByRole('button', { name: 'Download combined CSV' }).click();
  const download = await downloading;
  expect(download.suggestedFilename()).toMatch(/^ray-tracer-quest-class-\d{4}-\d{2}-\d{2}\.csv$/);
  const csv = parseCsv(await readFile(await download.path(), 'utf8'));
  if (!csv.ok) throw new Error(csv.error);
  const [header, ...rows] = csv.rows;
  expect(header.slice(0, 9)).toEqual(['learner_id', 'attempt_id', 'install_id', 'participant', 'assignment', 'assignment_id', 'class_code', 'level', 'task']);
  expect(header).toContain('survey_learned-soft-shadows');
  expect(rows).toHaveLength(expected.records.reduce((total, record) => total + record.attempts.length, 0));
  expect(new Set(rows.map((row) => row[header.indexOf('participant')]))).toEqual(new Set(expected.records.map((record) => record.participant)));
  expect(errors).toEqual([]);
});

test('the dashboard works at 1024×768 and clears', async ({ page }) => {
  await page.setViewportSize({ width: 1024, height: 768 });
  await page.goto('./#/dashboard');
  const dashboard = page.locator('rt-dashboard-page');
  await dashboard
    .locator('input[type=file]')
    .setInputFiles(files.slice(0, 3).map((file) => ({ name: file.name, mimeType: 'application/json', buffer: Buffer.from(file.text) })));
  await expect(dashboard.getByRole('status')).toHaveText('3 students counted, 0 files skipped.');
  const width = await page.evaluate(() => document.documentElement.scrollWidth);
  expect(width).toBeLessThanOrEqual(1024);
  await dashboard.getByRole('button', { name: 'Clear' }).click();
  await expect(dashboard.locator('section.level')).toHaveCount(0);
  await expect(dashboard.getByRole('button', { name: 'Download combined CSV' })).toBeDisabled();
});
