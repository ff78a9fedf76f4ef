import { expect, test, type Locator, type Page } from '@playwright/test';
import { readFileSync } from 'node:fs';
import type { Assignment } from '../src/classroom/assignment.ts';
import { decodeAssignment } from '../src/classroom/assignment-link.ts';
import { parseCsv } from '../src/classroom/csv-text.ts';
import { eventLogSchema } from '../src/quest/event-log.ts';
import { answerDefaultSurvey, download } from './support/classroom-steps.ts';
import { closeRenderWindow, collectErrors, playLevel1UpToTheRayTracer, renderFirstImage } from './support/game-steps.ts';

// The classroom as a teacher and a student use it: build an assignment on #/teacher, open
// its link as a student (participant code), play it, answer the survey and download the
// results; the survey's checks; a mangled link that falls back to free play with a message.

/**
 * The teacher page's link once it says `expected`: the link is remade (compressed) a moment
 * after each change, so reading it straight after a click can give the one before.
 */
async function linkFor(teacher: Locator, expected: Partial<Assignment>): Promise<string> {
  const link = teacher.getByRole('textbox', { name: 'Assignment link' });
  const decoded = async () => {
    const hash = (await link.inputValue()).replace(/^[^#]*/, '');
    const read = await decodeAssignment(hash);
    return read.ok ? read.assignment : read.reasons;
  };
  await expect.poll(decoded).toMatchObject(expected);
  return link.inputValue();
}

/** Builds the assignment of the spec's scenario and returns its link. */
async function buildAssignment(page: Page): Promise<string> {
  await page.goto('./#/teacher');
  const teacher = page.locator('rt-teacher-page');
  await teacher.getByRole('textbox', { name: /Title/ }).fill('Lesson 2, "rays"');
  await teacher.getByRole('combobox', { name: 'Add a level' }).selectOption({ label: 'Rays from the camera' });
  await teacher.getByRole('button', { name: 'Add', exact: true }).click();
  await expect(teacher.locator('li[data-level]')).toHaveCount(2);
  // Order: move level 2 up and back down with the buttons.
  await teacher.getByRole('button', { name: 'Move Rays from the camera up' }).click();
  await expect(teacher.locator('li[data-level]').first()).toHaveAttribute('data-level', '02-rays-from-the-camera');
  await teacher.getByRole('button', { name: 'Move Rays from the camera down' }).click();
  await expect(teacher.locator('li[data-level]').first()).toHaveAttribute('data-level', '01-introduction');
  // An optional task made required.
  await teacher.getByRole('checkbox', { name: /Slide the view/ }).check();
  await teacher.getByRole('radio', { name: /Ask for a code/ }).check();
  await teacher.getByRole('radio', { name: /standard questions/ }).check();

  const link = teacher.getByRole('textbox', { name: 'Assignment link' });
  await expect(link).toHaveValue(/#\/a\/1\.[A-Za-z0-9_-]+$/);
  const url = await linkFor(teacher, { levels: ['01-introduction', '02-rays-from-the-camera'], askParticipantCode: true, survey: 'default' });
  await expect(teacher.getByRole('img', { name: 'QR code of the assignment link' })).toBeVisible();
  await teacher.getByRole('button', { name: 'Copy link' }).click();
  await expect(teacher.locator('section[aria-labelledby="result-heading"]').getByRole('status')).toHaveText(/copied|Ctrl\+C/);
  await expect(teacher.getByRole('link', { name: 'Open as a student' })).toHaveAttribute('href', url);
  return url;
}

test('a teacher builds an assignment; a student opens its link and enters a code', async ({ page, context }) => {
  const errors = collectErrors(page);
  await context.grantPermissions(['clipboard-read', 'clipboard-write']);
  const url = await buildAssignment(page);
  expect(await page.evaluate(() => navigator.clipboard.readText())).toBe(url);
  expect(url.length).toBeLessThan(500);

  await page.goto(url);
  const lab = page.locator('rt-lab');
  await expect(lab).toBeAttached();
  const assignment = await lab.evaluate((element) => (element as unknown as { assignment: unknown }).assignment);
  expect(assignment).toMatchObject({
    title: 'Lesson 2, "rays"',
    levels: ['01-introduction', '02-rays-from-the-camera'],
    askParticipantCode: true,
    survey: 'default',
  });
  expect((assignment as { requiredTasks: Record<string, string[]> }).requiredTasks['01-introduction']).toContain('pan');

  const dialog = page.locator('rt-participant-dialog');
  await dialog.getByRole('button', { name: 'I understand, start' }).click();
  await expect(dialog.getByRole('textbox', { name: 'Participant code' })).toBeVisible();
  await dialog.getByRole('textbox', { name: 'Participant code' }).fill('P-07');
  await dialog.getByRole('button', { name: 'Start' }).click();
  await expect(dialog.getByRole('textbox', { name: 'Participant code' })).toBeHidden();
  await expect(page.locator('rt-link-notice')).toHaveCount(0);
  expect(errors).toEqual([]);
});

test('a mangled assignment link falls back to free play with a message', async ({ page }) => {
  const errors = collectErrors(page);
  const url = await buildAssignment(page);
  const mangled = url.slice(0, -8) + (url.endsWith('A') ? 'B' : 'A');
  await page.goto(mangled);
  const notice = page.locator('rt-link-notice').getByRole('alert');
  await expect(notice).toHaveText(/This assignment link is damaged \(.+\)\. You are playing freely\./);
  await expect(page.locator('rt-lab')).toBeAttached();
  expect(await page.locator('rt-lab').evaluate((element) => (element as unknown as { assignment: unknown }).assignment ?? null)).toBeNull();
  await notice.getByRole('button', { name: 'Dismiss message' }).click();
  await expect(notice).toBeHidden();

  // A link from a later version says so.
  await page.goto(url.replace('#/a/1.', '#/a/2.'));
  await expect(page.locator('rt-link-notice').getByRole('alert')).toHaveText(/another version of the game/);
  expect(errors).toEqual([]);
});

test('the survey says what is missing and hands in the answers', async ({ page }) => {
  const errors = collectErrors(page);
  await page.goto('./#/survey/default');
  const survey = page.locator('rt-survey');
  await survey.getByRole('button', { name: 'Hand in' }).click();
  await expect(survey.getByRole('alert')).toHaveText(/11 answers still need attention/);
  await expect(survey.getByRole('radio', { name: /^vmbo/ })).toBeFocused();

  await answerDefaultSurvey(survey, 'lots');
  await survey.getByRole('button', { name: 'Hand in' }).click();
  await expect(survey.getByRole('group', { name: /how many minutes/ })).toContainText('Please type a number, like 25.');

  const minutes = survey.getByRole('textbox', { name: /how many minutes/ });
  await minutes.fill('35');
  await minutes.press('Tab');
  const submitted = survey.evaluate(
    (element) => new Promise((resolve) => element.addEventListener('survey-submitted', (event) => resolve((event as CustomEvent).detail), { once: true })),
  );
  await survey.getByRole('button', { name: 'Hand in' }).click();
  expect(await submitted).toMatchObject({
    survey: 'default',
    answers: {
      education: 'havo',
      'computer-skill': 7,
      'prior-knowledge': 1,
      minutes: 35,
      'learned-supersampling': 5,
      ease: 'about-right',
      feedback: 'Nice, "really"\nthanks',
    },
  });
  await expect(survey.getByRole('status')).toHaveText(/Thank you/);
  expect(errors).toEqual([]);
});

// Node's loader wants an import attribute for JSON that vite does not: package.json is read as a file.
const { version } = JSON.parse(readFileSync('package.json', 'utf8')) as { version: string };
const ISO_TIME = /^\d{4}-\d\d-\d\dT\d\d:\d\d:\d\d\.\d{3}Z$/;
const ISO_DURATION = /^PT(?:(\d+)H)?(?:(\d+)M)?(?:(\d+(?:\.\d+)?)S)?$/;
/** The CSV columns that spec/classroom.md asks for (the export may have more). */
const SPEC_COLUMNS = [
  'participant',
  'assignment',
  'level',
  'task',
  'mandatory',
  'started_at',
  'completed_at',
  'duration_ms',
  'active_ms',
  'hints_text',
  'hints_guidance',
  'shown_by_app',
  'attempts',
  'points',
];

/** Milliseconds of an ISO 8601 duration as xAPI writes them (hours, minutes, seconds). */
function durationMs(text: string): number {
  const [, hours = '0', minutes = '0', seconds = '0'] = ISO_DURATION.exec(text) ?? [];
  return ((Number(hours) * 60 + Number(minutes)) * 60 + Number(seconds)) * 1000;
}

test('a student plays a one-level assignment, answers the survey and downloads CSV, JSON and xAPI', async ({ page }) => {
  const began = Date.now();
  const errors = collectErrors(page);
  const title = 'Lesson 1, "look around"';
  await page.goto('./#/teacher');
  const teacher = page.locator('rt-teacher-page');
  await teacher.getByRole('textbox', { name: /Title/ }).fill(title);
  await expect(teacher.locator('li[data-level]')).toHaveCount(1);
  await expect(teacher.locator('li[data-level]')).toHaveAttribute('data-level', '01-introduction');
  await teacher.getByRole('radio', { name: /Ask for a code/ }).check();
  await teacher.getByRole('radio', { name: /standard questions/ }).check();
  const url = await linkFor(teacher, { title, levels: ['01-introduction'], askParticipantCode: true, survey: 'default' });

  // The student: the link, a code, the level to its end.
  await page.goto(url);
  const dialog = page.locator('rt-participant-dialog');
  await dialog.getByRole('button', { name: 'I understand, start' }).click();
  await dialog.getByRole('textbox', { name: 'Participant code' }).fill('P-07');
  await dialog.getByRole('button', { name: 'Start' }).click();
  await expect(dialog.getByRole('textbox', { name: 'Participant code' })).toBeHidden();
  await page.getByRole('button', { name: 'Got it' }).click();
  await playLevel1UpToTheRayTracer(page);
  await renderFirstImage(page);
  await closeRenderWindow(page);

  // The assignment's only level is passed: its survey takes the task column.
  const survey = page.locator('rt-lab rt-survey');
  await expect(survey).toBeVisible();
  await answerDefaultSurvey(survey, '12');
  await survey.getByRole('button', { name: 'Hand in' }).click();
  // Handed in: the task column shows the finished level again.
  await expect(survey).toHaveCount(0);
  await expect(page.locator('rt-quest-panel').getByText('Level complete!')).toBeVisible();

  const csv = await download(page, 'Download CSV');
  const json = await download(page, 'Download results file');
  const xapi = await download(page, 'Download xAPI');
  const wallMs = Date.now() - began;
  expect(csv.name).toMatch(/^ray-tracer-quest-P-07-([A-Za-z0-9-]+-)?\d{4}-\d\d-\d\d-\d\dh\d\d-local\.csv$/);
  expect(json.name).toMatch(/^ray-tracer-quest-P-07-.+\.json$/);
  expect(xapi.name).toMatch(/^ray-tracer-quest-P-07-.+\.xapi\.json$/);
  const inTest = (iso: string) => Date.parse(iso) >= began - 1000 && Date.parse(iso) <= began + wallMs + 1000;

  // JSON: the whole event log, the app's version, the survey answers.
  const exported = JSON.parse(json.text) as {
    format: string;
    appVersion: string;
    participant: string;
    assignment: { title: string; levels: string[] };
    events: unknown;
    survey: { survey: string; answers: Record<string, unknown> };
  };
  expect(exported).toMatchObject({
    format: 'ray-tracer-quest-export',
    appVersion: version,
    participant: 'P-07',
    assignment: { title, levels: ['01-introduction'] },
  });
  expect(exported.survey).toMatchObject({
    survey: 'default',
    answers: { education: 'havo', 'computer-skill': 7, minutes: 12, ease: 'about-right', feedback: 'Nice, "really"\nthanks' },
  });
  const log = eventLogSchema.parse(exported.events);
  const types = log.events.map((event) => event.type);
  for (const type of ['session.started', 'level.opened', 'task.shown', 'hint.shown', 'task.completed', 'level.passed']) expect(types).toContain(type);
  const completed = log.events.flatMap((event) => (event.type === 'task.completed' ? [event] : []));
  const required = ['orbit', 'zoom', 'select-ball', 'color-ball', 'move-ball', 'deselect', 'open-render'];
  expect(completed.map((event) => event.task)).toEqual(required);
  expect(completed.find((event) => event.task === 'select-ball')?.how).toBe('shown');
  expect(log.events.at(-1)!.t).toBeLessThan(wallMs);

  // CSV: the spec's columns, one row per task attempt (a task shown), the code in every row.
  expect(csv.text.startsWith('\uFEFF')).toBe(true);
  // The title's comma and quotes are escaped (RFC 4180).
  expect(csv.text).toContain('"Lesson 1, ""look around"""');
  const read = parseCsv(csv.text);
  if (!read.ok) throw new Error(read.error);
  const [header, ...lines] = read.rows;
  expect(header).toEqual(expect.arrayContaining(SPEC_COLUMNS));
  const rows = lines.map((line) => Object.fromEntries(header.map((column, i) => [column, line[i]])));
  // A row per required task shown, and per optional task the student touched (none here).
  const requiredShown = log.events.filter((event) => event.type === 'task.shown' && event.required).length;
  expect(rows).toHaveLength(requiredShown + types.filter((type) => type === 'task.started').length);
  for (const row of rows) {
    expect(row).toMatchObject({ participant: 'P-07', assignment: title, level: '01-introduction', attempts: '1' });
    expect(row.started_at).toMatch(ISO_TIME);
    expect(inTest(row.started_at)).toBe(true);
    expect(Number(row.active_ms)).toBeLessThanOrEqual(Number(row.duration_ms));
    expect(Number(row.duration_ms)).toBeLessThan(wallMs);
  }
  const done = rows.filter((row) => row.completed_at !== '');
  expect(done.map((row) => row.task)).toEqual(required);
  for (const row of done) {
    expect(row.completed_at).toMatch(ISO_TIME);
    expect(inTest(row.completed_at)).toBe(true);
    expect(row.mandatory).toBe('true');
    expect(Number(row.duration_ms), row.task).toBeGreaterThan(0);
    expect(Number(row.active_ms), row.task).toBeGreaterThan(0);
    expect(Math.abs(Date.parse(row.completed_at) - Date.parse(row.started_at) - Number(row.duration_ms))).toBeLessThanOrEqual(1);
    expect(Number(row.points)).toBeGreaterThanOrEqual(0);
  }
  const byTask = (id: string) => done.find((row) => row.task === id)!;
  expect(byTask('zoom')).toMatchObject({ hints_text: '2', hints_guidance: '1', shown_by_app: 'false' });
  expect(byTask('select-ball')).toMatchObject({ hints_text: '1', hints_guidance: '1', shown_by_app: 'true' });
  expect(byTask('orbit')).toMatchObject({ hints_text: '0', hints_guidance: '0', shown_by_app: 'false' });

  // xAPI: statements with actor, verb, object and timestamp; durations in ISO 8601.
  const statements = JSON.parse(xapi.text) as {
    actor: { account: { name: string } };
    verb: { id: string };
    object: { id: string };
    timestamp: string;
    result?: { duration?: string; response?: string };
  }[];
  expect(Array.isArray(statements)).toBe(true);
  for (const statement of statements) {
    expect(statement.actor.account.name).toBe('P-07');
    expect(statement.verb.id).toMatch(/^https?:\/\//);
    expect(statement.object.id).toMatch(/^https?:\/\//);
    expect(statement.timestamp).toMatch(ISO_TIME);
    if (statement.result?.duration !== undefined) {
      expect(statement.result.duration).toMatch(ISO_DURATION);
      expect(statement.result.duration).not.toBe('PT');
      expect(durationMs(statement.result.duration)).toBeLessThan(wallMs);
    }
  }
  const verb = (ending: string) => statements.filter((statement) => statement.verb.id.endsWith(ending));
  const taskCompletions = verb('/completed').filter((statement) => statement.object.id.includes('01-introduction'));
  expect(taskCompletions).toHaveLength(required.length);
  for (const row of done) {
    const statement = taskCompletions.find((s) => s.object.id.endsWith(`/${row.task}`))!;
    expect(Math.abs(durationMs(statement.result!.duration!) - Number(row.duration_ms))).toBeLessThanOrEqual(5);
  }
  expect(verb('/passed')).toHaveLength(1);
  expect(verb('/passed')[0].result?.duration).toMatch(ISO_DURATION);
  expect(verb('/answered').map((statement) => statement.result?.response)).toContain('havo');

  // The teacher's dashboard reads the JSON file and shows the level.
  await page.goto('./#/dashboard');
  const dashboard = page.locator('rt-dashboard-page');
  await dashboard.locator('input[type=file]').setInputFiles({ name: json.name, mimeType: 'application/json', buffer: Buffer.from(json.text) });
  await expect(dashboard.getByRole('status').filter({ hasText: '1 student counted' })).toBeVisible();
  await expect(dashboard.locator('section.level[data-level="01-introduction"]')).toBeVisible();
  expect(errors).toEqual([]);
});
