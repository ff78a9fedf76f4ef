import { expect, test, type Page } from '@playwright/test';

// The classroom as a teacher and a student use it: build an assignment on #/teacher, open
// its link as a student (participant code), the survey, and a mangled link that falls back
// to free play with a message.

function collectErrors(page: Page): string[] {
  const errors: string[] = [];
  page.on('console', (message) => {
    if (message.type() === 'error') errors.push(message.text());
  });
  page.on('pageerror', (error) => errors.push(error.message));
  return errors;
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
  await expect(teacher.getByRole('img', { name: 'QR code of the assignment link' })).toBeVisible();
  await teacher.getByRole('button', { name: 'Copy link' }).click();
  await expect(teacher.getByRole('status')).toHaveText(/copied|Ctrl\+C/);
  const url = await link.inputValue();
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
  await expect(survey.getByRole('radio', { name: 'Primary school' })).toBeFocused();

  await survey.getByRole('radio', { name: 'Secondary school' }).check();
  await survey.getByRole('group', { name: /good are you with computers/ }).getByRole('radio', { name: '7' }).check();
  await survey.getByRole('group', { name: /before you started/ }).getByRole('radio', { name: '1, Not at all' }).check();
  const minutes = survey.getByRole('textbox', { name: /how many minutes/ });
  await minutes.fill('lots');
  await minutes.press('Tab');
  for (const name of [/ray tracing in general/, /kinds of light source/, /distance and angle/, /soft shadows/, /supersampling/, /ways of showing rays/]) {
    await survey.getByRole('group', { name }).getByRole('radio', { name: '5, Helped a lot' }).check();
  }
  await survey.getByRole('radio', { name: 'About right' }).check();
  await survey.getByRole('textbox', { name: /other feedback/ }).fill('Nice, "really"\nthanks');
  await survey.getByRole('button', { name: 'Hand in' }).click();
  await expect(survey.getByRole('group', { name: /how many minutes/ })).toContainText('Please type a number, like 25.');

  await minutes.fill('35');
  await minutes.press('Tab');
  const submitted = survey.evaluate(
    (element) => new Promise((resolve) => element.addEventListener('survey-submitted', (event) => resolve((event as CustomEvent).detail), { once: true })),
  );
  await survey.getByRole('button', { name: 'Hand in' }).click();
  expect(await submitted).toMatchObject({
    survey: 'default',
    answers: { education: 'secondary', 'computer-skill': 7, 'prior-knowledge': 1, minutes: 35, 'learned-supersampling': 5, ease: 'about-right', feedback: 'Nice, "really"\nthanks' },
  });
  await expect(survey.getByRole('status')).toHaveText(/Thank you/);
  expect(errors).toEqual([]);
});
