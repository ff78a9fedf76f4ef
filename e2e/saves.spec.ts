import { expect, test, type Page } from '@playwright/test';
import { readFile } from 'node:fs/promises';
import type { Assignment } from '../src/classroom/assignment.ts';
import { encodeAssignment } from '../src/classroom/assignment-link.ts';
import type { LabAction } from '../src/lab-state/lab-action.ts';
import { answerDefaultSurvey } from './support/classroom-steps.ts';
import { collectErrors, progressFile, state } from './support/game-steps.ts';

// Saves that fail are said, and nothing is lost: the browser's real localStorage is filled
// until it refuses, then the learner imports progress, hands in the survey, resets. Every
// message shows above the level map, in the page's live regions. A sandbox edit is there
// after a reload that follows it at once. A damaged session record and damaged survey
// answers are said, and kept to download (and restore) from the Menu.

/** Fills the page's localStorage until it refuses even a few characters (other data of this site). */
async function fillStorage(page: Page): Promise<void> {
  await page.evaluate(() => {
    let index = 0;
    for (const size of [1 << 20, 1 << 16, 1 << 12, 1 << 8, 16, 1]) {
      const chunk = 'x'.repeat(size);
      try {
        for (;;) localStorage.setItem(`filler.${index++}`, chunk);
      } catch {
        // Full at this size: go on with smaller pieces.
      }
    }
  });
}

async function freeStorage(page: Page): Promise<void> {
  await page.evaluate(() =>
    Object.keys(localStorage)
      .filter((key) => key.startsWith('filler.'))
      .forEach((key) => localStorage.removeItem(key)),
  );
}

/** The toast that says `text` is seen, announced (in `role` region), and is what is on top where it is drawn. */
async function expectToastOnTop(page: Page, text: string | RegExp, role: 'status' | 'alert'): Promise<void> {
  const toast = page.locator('rt-toast .toast').filter({ hasText: text });
  await expect(toast).toBeVisible();
  await expect(page.locator(`rt-toast [role="${role}"]`)).toContainText(text);
  const box = (await toast.boundingBox())!;
  const hit = await page.evaluate(({ x, y }) => (document.querySelector('rt-lab')!.shadowRoot!.elementFromPoint(x, y) as Element | null)?.tagName ?? null, {
    x: box.x + box.width / 2,
    y: box.y + box.height / 2,
  });
  expect(hit).toBe('RT-TOAST');
}

async function importFile(page: Page, text: string): Promise<void> {
  await page.getByRole('button', { name: 'Menu' }).click();
  await page.locator('rt-progress-menu input[type=file]').setInputFiles({ name: 'progress.json', mimeType: 'application/json', buffer: Buffer.from(text) });
}

test('with storage full an import is refused and said, over the level map; with room it is imported, and a reset is said there too', async ({ page }) => {
  const errors = collectErrors(page);
  await page.goto('./');
  await page.getByRole('button', { name: 'Got it' }).click();
  await page.locator('[data-command="levels"]').click();
  const map = page.locator('rt-level-map');
  await expect(map).toBeVisible();
  await expect(map.locator('[data-level="02-rays-from-the-camera"]')).toHaveAttribute('data-status', 'locked');

  await fillStorage(page);
  // A file larger than the progress saved now, which it would replace: it cannot fit.
  const progress = JSON.parse(progressFile(['01-introduction', '02-rays-from-the-camera', '32-match-the-shot']));
  progress.log.events = Array.from({ length: 400 }, (_, index) => ({ t: index * 1000, id: `old.${index}`, type: index % 2 ? 'tab.visible' : 'tab.hidden' }));
  const file = JSON.stringify(progress);
  await importFile(page, file);
  await expectToastOnTop(
    page,
    /progress\.json \(2\d kB\) was not imported: the browser's storage has no room for it\. Nothing changed: your progress is as it was\./,
    'alert',
  );
  await page.keyboard.press('Escape');
  // The map is over the toast's place: the test shows the toast above it.
  const mapBox = (await map.boundingBox())!;
  const toastBox = (await page.locator('rt-toast .toast').first().boundingBox())!;
  expect(toastBox.y).toBeGreaterThan(mapBox.y);
  expect(toastBox.y + toastBox.height).toBeLessThan(mapBox.y + mapBox.height);
  await expect(map.locator('[data-level="02-rays-from-the-camera"]')).toHaveAttribute('data-status', 'locked');
  await page.screenshot({ path: 'test-results/screens/saves-import-refused.png' });

  await freeStorage(page);
  await importFile(page, file);
  await expectToastOnTop(page, 'Progress imported from progress.json.', 'status');
  await page.keyboard.press('Escape');
  await expect(map.locator('[data-level="03-shading"]')).toHaveAttribute('data-status', 'open');
  await page.reload();
  await page.locator('[data-command="levels"]').click();
  await expect(map.locator('[data-level="03-shading"]')).toHaveAttribute('data-status', 'open');

  await page.getByRole('button', { name: 'Menu' }).click();
  await page.getByRole('button', { name: 'Reset progress…' }).click();
  await page.locator('rt-progress-menu dialog').getByRole('button', { name: 'Reset' }).click();
  await expect(map).toBeVisible();
  await expectToastOnTop(page, 'Your progress was reset. Start again from the level map.', 'status');
  await page.screenshot({ path: 'test-results/screens/saves-reset-over-map.png' });
  expect(errors).toEqual([]);
});

test('a survey handed in with storage full is said not saved, kept, and saved when the page is left with room', async ({ page }) => {
  const assignment: Assignment = {
    version: 1,
    title: 'Lesson 4',
    levels: ['01-introduction'],
    requiredTasks: { '01-introduction': [] },
    otherLevels: 'hidden',
    locale: 'en',
    askParticipantCode: false,
    survey: 'default',
  };
  await page.goto(`./${await encodeAssignment(assignment)}`);
  const survey = page.locator('rt-lab rt-survey');
  await answerDefaultSurvey(survey, '12');
  await fillStorage(page);
  await survey.getByRole('button', { name: 'Hand in' }).click();
  await expectToastOnTop(
    page,
    /Thank you! Your answers could not be saved in the browser: the browser's storage has no room for it\. They are kept while this page is open: download your data below now for your teacher\./,
    'alert',
  );
  await expect(page.getByText('Your answers are saved')).toHaveCount(0);
  await expect(survey).toHaveCount(0);

  // Room again; leaving the page (a reload) writes what waited: the survey is not asked again.
  await freeStorage(page);
  await page.reload();
  await expect(page.locator('rt-assignment-done')).toBeVisible();
  await expect(page.locator('rt-lab rt-survey')).toHaveCount(0);
  const kept = await page.evaluate(() =>
    Object.keys(localStorage)
      .filter((key) => key.endsWith('.survey'))
      .map((key) => JSON.parse(localStorage.getItem(key)!)),
  );
  expect(kept).toMatchObject([{ survey: 'default', answers: { minutes: 12 } }]);
});

test('a sandbox edit is there after the page is reloaded or closed a moment after it', async ({ page, context }) => {
  const dispatch = (action: LabAction, live = false) =>
    page.evaluate(
      ([sent, dragging]) =>
        (document.querySelector('rt-lab') as unknown as { store: { dispatch(a: LabAction, o: object): void } }).store.dispatch(sent, { live: dragging }),
      [action, live] as const,
    );
  await page.goto('./#free-lab');
  await expect(page.locator('rt-file-panel')).toBeVisible();
  const before = (await state(page)).scene.objects.length;
  await dispatch({ type: 'object.added', shape: 'sphere' });
  const id = (await state(page)).scene.objects.at(-1)!.id;
  // Still being dragged (a value the store marks live): waits for rest, or for the page to be left.
  await dispatch({ type: 'object.changed', id, changes: { position: [1.25, 0.5, -0.75] } }, true);
  await page.reload();
  await expect(page.locator('rt-file-panel')).toBeVisible();
  const after = (await state(page)).scene;
  expect(after.objects).toHaveLength(before + 1);
  expect(after.objects.find((object) => object.id === id)?.position).toEqual([1.25, 0.5, -0.75]);

  await dispatch({ type: 'object.changed', id, changes: { position: [2, 0.5, 2] } }, true);
  // With runBeforeUnload, close() returns before the page has gone: wait for its pagehide to run.
  const closed = page.waitForEvent('close');
  await page.close({ runBeforeUnload: true });
  await closed;
  const again = await context.newPage();
  await again.goto('./#free-lab');
  await expect(again.locator('rt-file-panel')).toBeVisible();
  const scene = await again.evaluate(
    () => (document.querySelector('rt-lab') as unknown as { store: { state: { scene: { objects: { id: string; position: number[] }[] } } } }).store.state.scene,
  );
  expect(scene.objects.find((object) => object.id === id)?.position).toEqual([2, 0.5, 2]);
});

test('a damaged session record is said in the code dialog, and kept in the Menu to download', async ({ page, context }) => {
  const hash = await encodeAssignment({
    version: 1,
    title: 'Lesson 5',
    levels: ['01-introduction'],
    requiredTasks: {},
    otherLevels: 'hidden',
    locale: 'en',
    askParticipantCode: true,
    survey: null,
  });
  await page.goto(`./${hash}`);
  await page.locator('rt-participant-dialog').getByRole('button', { name: 'I understand, start' }).click();
  await page.locator('rt-participant-dialog').getByRole('textbox', { name: 'Participant code' }).fill('A17');
  await page.locator('rt-participant-dialog').getByRole('button', { name: 'Start' }).click();
  await expect(page.locator('rt-participant-dialog').getByRole('textbox')).toBeHidden();
  // The record is damaged while no page of the assignment is open (it would save over it on
  // leaving); free play, open meanwhile, keeps its own records.
  const damaged = '{"participantCode": 17, "attemptId": "nope"';
  const later = await context.newPage();
  await page.close();
  await later.goto('./');
  await later.evaluate(
    (text) =>
      Object.keys(localStorage)
        .filter((key) => key.endsWith('.context'))
        .forEach((key) => localStorage.setItem(key, text)),
    damaged,
  );
  await later.goto(`./${hash}`);

  const dialog = later.locator('rt-participant-dialog');
  await dialog.getByRole('button', { name: 'I understand, start' }).click();
  await expect(dialog.locator('#code-note')).toContainText('Your saved participant code could not be read: please type it again.');
  await expect(dialog.locator('#code-note')).toContainText('The damaged record is kept: download or restore it from the Menu (Damaged saves).');
  await dialog.getByRole('textbox', { name: 'Participant code' }).fill('A17');
  await dialog.getByRole('button', { name: 'Start' }).click();
  await later.getByRole('button', { name: 'Menu' }).click();
  const entry = later.locator('rt-progress-menu [data-damaged-save]');
  await expect(entry).toContainText('Participant code and attempt, kept on');
  const started = later.waitForEvent('download');
  await entry.getByRole('button', { name: 'Download' }).click();
  const file = await started;
  expect(file.suggestedFilename()).toMatch(/^ray-tracer-quest-damaged-session-record-\d{4}-\d\d-\d\dT\d\d-\d\d-\d\d\.json$/);
  expect(await readFile(await file.path(), 'utf8')).toBe(damaged);
});

const surveyAssignment: Assignment = {
  version: 1,
  title: 'Lesson 6',
  levels: ['01-introduction'],
  requiredTasks: { '01-introduction': [] },
  otherLevels: 'hidden',
  locale: 'en',
  askParticipantCode: false,
  survey: 'default',
};

/** Hands in the survey of `surveyAssignment`, then damages its record (`damage` of the saved text) with no page of it open; returns that page and the damaged text. */
async function damagedSurvey(page: Page, damage: (saved: string) => string): Promise<{ later: Page; hash: string; damaged: string }> {
  const hash = await encodeAssignment(surveyAssignment);
  await page.goto(`./${hash}`);
  const survey = page.locator('rt-lab rt-survey');
  await answerDefaultSurvey(survey, '12');
  await survey.getByRole('button', { name: 'Hand in' }).click();
  await expect(page.locator('rt-assignment-done')).toBeVisible();
  const later = await page.context().newPage();
  await page.close();
  await later.goto('./');
  const key = await later.evaluate(() => Object.keys(localStorage).find((name) => name.endsWith('.survey'))!);
  const damaged = damage(await later.evaluate((name) => localStorage.getItem(name)!, key));
  await later.evaluate(([name, text]) => localStorage.setItem(name!, text!), [key, damaged]);
  return { later, hash, damaged };
}

test('damaged survey answers are said, kept in the Menu, downloaded and restored', async ({ page }) => {
  // Cut short inside the last answer (the free text): the answers before the cut are kept.
  const { later, hash, damaged } = await damagedSurvey(page, (saved) => saved.slice(0, saved.indexOf('really')));
  await later.goto(`./${hash}`);
  await expectToastOnTop(
    later,
    /Your saved survey answers were damaged; what could be read of them is kept \(\d+ answers\)\. The damaged answers are kept: download or restore them from the Menu \(Damaged saves\)\./,
    'alert',
  );
  await expect(later.locator('rt-assignment-done')).toBeVisible();
  const stored = () => later.evaluate(() => JSON.parse(localStorage.getItem(Object.keys(localStorage).find((key) => key.endsWith('.survey'))!)!));
  expect((await stored()).answers).not.toHaveProperty('feedback');

  await later.getByRole('button', { name: 'Menu' }).click();
  const entry = later.locator('rt-progress-menu [data-damaged-save]');
  await expect(entry).toContainText('Survey answers, kept on');
  const started = later.waitForEvent('download');
  await entry.getByRole('button', { name: 'Download' }).click();
  const file = await started;
  expect(file.suggestedFilename()).toMatch(/^ray-tracer-quest-damaged-survey-answers-\d{4}-\d\d-\d\dT\d\d-\d\d-\d\d\.json$/);
  expect(await readFile(await file.path(), 'utf8')).toBe(damaged);
  await entry.getByRole('button', { name: 'Restore' }).click();
  await expectToastOnTop(later, 'The damaged save is restored', 'status');
  expect((await stored()).answers).toMatchObject({ minutes: 12, education: 'havo' });
  await later.screenshot({ path: 'test-results/screens/saves-damaged-survey.png' });
});

test('damaged survey answers with the storage full are not written over by the survey handed in again until downloaded', async ({ page }) => {
  // The survey's id is gone: nothing can be used, and the survey asks again.
  const { later, hash, damaged } = await damagedSurvey(page, (saved) => saved.replace('"survey":"default"', '"survey":17'));
  await fillStorage(later);
  await later.goto(`./${hash}`);
  await expectToastOnTop(
    later,
    /Your saved survey answers could not be read, so the survey will ask for them again\. There is no room to keep a copy of the damaged answers, so they are not written over until you download them from the Menu \(Damaged saves\)\./,
    'alert',
  );
  const survey = later.locator('rt-lab rt-survey');
  await answerDefaultSurvey(survey, '15');
  await survey.getByRole('button', { name: 'Hand in' }).click();
  // The progress cannot be saved either: the first reason is said (the damaged answers' was said at the start).
  await expectToastOnTop(later, /Your answers could not be saved in the browser: the browser's storage has no room for it\./, 'alert');
  const stored = () => later.evaluate(() => localStorage.getItem(Object.keys(localStorage).find((key) => key.endsWith('.survey'))!));
  expect(await stored()).toBe(damaged);

  await later.getByRole('button', { name: 'Menu' }).click();
  const entry = later.locator('rt-progress-menu [data-damaged-save]');
  await expect(entry).toContainText('Survey answers, not copied (no room)');
  await later.screenshot({ path: 'test-results/screens/saves-damaged-survey-held.png' });
  const started = later.waitForEvent('download');
  await entry.getByRole('button', { name: 'Download' }).click();
  expect(await readFile(await (await started).path(), 'utf8')).toBe(damaged);
  await expect(entry).toHaveCount(0);
  // Saving goes on once there is room: leaving the page writes the answers handed in again.
  await freeStorage(later);
  await later.reload();
  await expect(later.locator('rt-assignment-done')).toBeVisible();
  expect(JSON.parse((await stored())!)).toMatchObject({ survey: 'default', answers: { minutes: 15 } });
});
