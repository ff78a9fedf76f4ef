import { expect, test, type Locator } from '@playwright/test';
import type { Assignment } from '../src/classroom/assignment.ts';
import { encodeAssignment } from '../src/classroom/assignment-link.ts';
import { parseCsv } from '../src/classroom/csv-text.ts';
import { expectAccessible } from './support/axe.ts';
import { answerDefaultSurvey, download } from './support/classroom-steps.ts';
import { closeRenderWindow, collectErrors, playLevel1UpToTheRayTracer, renderFirstImage } from './support/game-steps.ts';

// One student, one learner: a student who waits 10 s before typing their code, downloads a
// file midway, reloads, downloads again, finishes the level and the survey and presses two
// more buttons. The first task's time leaves the code dialog out; the CSV has the survey's
// columns; the dashboard counts the four files as one learner who passed; reloading the
// finished assignment shows its end, not its last level.

const CODE_WAIT_MS = 10_000;

const assignment: Assignment = {
  version: 1,
  title: 'Lesson 1',
  levels: ['01-introduction'],
  requiredTasks: {},
  otherLevels: 'hidden',
  locale: 'en',
  askParticipantCode: true,
  survey: 'default',
  classCode: '3B',
};

const rowsOf = (text: string) => {
  const read = parseCsv(text);
  if (!read.ok) throw new Error(read.error);
  const [header, ...lines] = read.rows;
  return lines.map((line) => Object.fromEntries(header.map((column, index) => [column, line[index]])));
};

test('one student hands in four files: the dashboard shows one learner who passed', async ({ page }) => {
  test.setTimeout(240_000);
  const errors = collectErrors(page);
  await page.goto(`./${await encodeAssignment(assignment)}`);

  // The code dialog stays open for 10 s: nothing is timed yet.
  const dialog = page.locator('rt-participant-dialog');
  // First what is recorded and that taking part is voluntary; the code only after "I understand".
  await expect(dialog.getByText('Taking part is voluntary.')).toBeVisible();
  await dialog.getByRole('button', { name: 'I understand, start' }).click();
  await expect(dialog.getByRole('textbox', { name: 'Participant code' })).toBeVisible();
  await page.waitForTimeout(CODE_WAIT_MS);
  await dialog.getByRole('textbox', { name: 'Participant code' }).fill('007');
  const codeGiven = Date.now();
  await dialog.getByRole('button', { name: 'Start' }).click();
  await expect(dialog.getByRole('textbox', { name: 'Participant code' })).toBeHidden();
  // A newcomer is welcomed once the first level opens, after the code as without one.
  await expect(page.getByText('Welcome to Ray Tracer Quest!')).toBeVisible();
  await page.getByRole('button', { name: 'Got it' }).click();

  await playLevel1UpToTheRayTracer(page);
  const midway = await download(page, 'Download results file');
  await page.reload();
  await expect(page.locator('rt-task-card[status="current"]')).toContainText('Open the ray tracer');
  const afterReload = await download(page, 'Download results file');
  await renderFirstImage(page);
  await closeRenderWindow(page);
  const survey = page.locator('rt-lab rt-survey');
  await answerDefaultSurvey(survey, '12');
  await survey.getByRole('button', { name: 'Hand in' }).click();
  await expect(survey).toHaveCount(0);
  const finalJson = await download(page, 'Download results file');
  const finalCsv = await download(page, 'Download CSV');

  // The CSV: the first task timed from the code, the survey in its own columns, the code kept as text.
  expect(finalCsv.text).toContain('"007"');
  const rows = rowsOf(finalCsv.text);
  const look = rows.find((row) => row.task === 'orbit')!;
  expect(Date.parse(look.started_at)).toBeGreaterThanOrEqual(codeGiven - 1000);
  expect(Number(look.duration_ms)).toBeLessThan(CODE_WAIT_MS);
  for (const row of rows) {
    expect(row).toMatchObject({
      participant: '007',
      learner_id: '007',
      class_code: '3B',
      survey: 'default',
      survey_education: 'havo',
      survey_minutes: '12',
      'survey_computer-skill': '7',
    });
    expect(row.attempt_id).toMatch(/^[0-9a-f-]{36}$/);
  }
  expect(new Set(rows.map((row) => row.attempt_id)).size).toBe(1);
  const ids = [midway, afterReload, finalJson].map((file) => (JSON.parse(file.text) as { learner: { attemptId: string } }).learner.attemptId);
  expect(new Set([...ids, rows[0].attempt_id]).size).toBe(1);

  // Reloading the finished assignment shows its end, not the level.
  await page.reload();
  await expect(page.locator('rt-assignment-done').getByRole('heading', { name: 'Assignment finished' })).toBeVisible();
  await expect(page.locator('rt-quest-panel')).toHaveCount(0);

  // The teacher drops all four files: one learner, who passed.
  await page.goto('./#/dashboard');
  const dashboard = page.locator('rt-dashboard-page');
  const files = [midway, afterReload, finalJson, finalCsv].map((file, index) => ({
    name: `${index}-${file.name}`,
    mimeType: file.name.endsWith('.csv') ? 'text/csv' : 'application/json',
    buffer: Buffer.from(file.text),
  }));
  await dashboard.locator('input[type=file]').setInputFiles(files);
  await expect(dashboard.getByRole('status')).toHaveText(/1 student counted \(from 4 files: 3 merged into their student's\), 0 files skipped\./);
  await expect(dashboard.locator('section.level[data-level="01-introduction"] .level-facts')).toContainText('1 of 1 students passed');
  expect(errors).toEqual([]);
});

test('the survey has a readable page of its own over the lab at 1366×768, and on a phone', async ({ page }) => {
  const errors = collectErrors(page);
  await page.setViewportSize({ width: 1366, height: 768 });
  // No required task: the assignment is passed at once and its survey's page covers the lab.
  const hash = await encodeAssignment({ ...assignment, requiredTasks: { '01-introduction': [] }, askParticipantCode: false });
  await page.goto(`./${hash}`);
  const surveyPage = page.getByRole('region', { name: 'Closing survey' });
  const survey = surveyPage.locator('rt-survey');
  await expect(survey.getByRole('radio', { name: /^vmbo/ })).toBeVisible();
  await expect(surveyPage).toBeFocused();
  // A question reads as lines of words: wider than 500 px (about 6 words a line at least), its scale's steps in one row.
  expect((await survey.locator('fieldset').first().boundingBox())!.width).toBeGreaterThan(500);
  await expectWordsPerLine(survey, 6);
  await expectScalesInOneRow(survey);
  await page.screenshot({ path: 'test-results/screens/survey-page.png' });
  await expectAccessible(page, "the survey's page over the lab");

  // Later (or Esc) goes back to the lab; the task column offers the survey again.
  await surveyPage.getByRole('button', { name: 'Later' }).click();
  await expect(surveyPage).toHaveCount(0);
  const reopen = page.getByRole('complementary', { name: 'Tasks' }).getByRole('button', { name: 'Answer the questions' });
  await reopen.click();
  await expect(surveyPage).toBeVisible();
  await page.keyboard.press('Escape');
  await expect(surveyPage).toHaveCount(0);
  await expect(reopen).toBeFocused();
  await page.keyboard.press('Enter');
  await expect(surveyPage).toBeVisible();

  // At 200 % zoom (683×384 CSS px) the page covers the lab below the slim header: whole lines,
  // scales in one row, and its buttons a scroll away inside it, the page itself not scrolling.
  await page.setViewportSize({ width: 683, height: 384 });
  await expect(survey.getByRole('radio', { name: /^vmbo/ })).toBeVisible();
  expect((await survey.boundingBox())!.width).toBeGreaterThan(600);
  await expectWordsPerLine(survey, 6);
  await expectScalesInOneRow(survey);
  const handIn = surveyPage.getByRole('button', { name: 'Hand in' });
  await handIn.scrollIntoViewIfNeeded();
  const button = (await handIn.boundingBox())!;
  expect(button.y >= 0 && button.y + button.height <= 384, JSON.stringify(button)).toBe(true);
  expect(await page.evaluate(() => [document.documentElement.scrollWidth, document.documentElement.scrollHeight])).toEqual([683, 384]);
  await page.screenshot({ path: 'test-results/screens/survey-zoom-200.png' });

  // On a phone the page is as wide as the screen: whole lines, and each scale still in one row.
  await page.setViewportSize({ width: 390, height: 844 });
  await expect(survey.getByRole('radio', { name: /^vmbo/ })).toBeVisible();
  expect((await survey.boundingBox())!.width).toBeGreaterThan(370);
  await expectWordsPerLine(survey, 2);
  await expectScalesInOneRow(survey);
  await page.screenshot({ path: 'test-results/screens/survey-phone.png' });
  expect(errors).toEqual([]);
});

/** Each scale's steps (1 to 10, 1 to 5) side by side in one row. */
async function expectScalesInOneRow(survey: Locator): Promise<void> {
  const rows = await survey
    .locator('.scale .options')
    .evaluateAll((scales) =>
      scales.map((scale) => new Set([...scale.querySelectorAll('label')].map((label) => Math.round(label.getBoundingClientRect().top))).size),
    );
  // The survey leaves out the questions on ideas its assignment's levels do not teach: four scales are left for level 1.
  expect(rows.length).toBeGreaterThanOrEqual(4);
  expect(
    rows.every((count) => count === 1),
    JSON.stringify(rows),
  ).toBe(true);
}

/**
 * Every question and every option of four words or more (of `least` words or more when
 * that is more) is laid out at least `least` words to a line on average: a column squeezed to
 * a word's width (the bug of a survey sized by its content) breaks after every word.
 */
async function expectWordsPerLine(survey: Locator, least: number): Promise<void> {
  const squeezed = await survey.evaluate((element, least) => {
    const texts = [...element.shadowRoot!.querySelectorAll('legend, label, p')];
    return texts.flatMap((node) => {
      const words = (node.textContent ?? '').trim().split(/\s+/).length;
      if (words < Math.max(4, least)) return [];
      const range = document.createRange();
      range.selectNodeContents(node);
      // Inline boxes of one line (a span in a smaller font) start a few pixels apart; a new line starts a line's height lower.
      const tops = [...range.getClientRects()]
        .filter((rect) => rect.width > 0)
        .map((rect) => rect.top)
        .sort((a, b) => a - b);
      const lines = tops.filter((top, i) => i === 0 || top > tops[i - 1]! + 8).length;
      return words / lines < least
        ? [`${node.tagName} "${node.textContent?.trim()}": ${words} words on ${lines} lines, ${Math.round(node.getBoundingClientRect().width)} px wide`]
        : [];
    });
  }, least);
  expect(squeezed).toEqual([]);
}
