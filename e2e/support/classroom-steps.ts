import type { Locator, Page } from '@playwright/test';
import { readFile } from 'node:fs/promises';

// Steps of the classroom as a student takes them, shared by the classroom's specs.

/** Answers the default survey's required questions (and the feedback), typing `minutes` as the minutes spent. */
export async function answerDefaultSurvey(survey: Locator, minutes: string): Promise<void> {
  await survey.getByRole('radio', { name: /^havo/ }).check();
  await survey
    .getByRole('group', { name: /good are you with computers/ })
    .getByRole('radio', { name: '7' })
    .check();
  await survey
    .getByRole('group', { name: /before you started/ })
    .getByRole('radio', { name: '1, Not at all' })
    .check();
  await survey.getByRole('textbox', { name: /how many minutes/ }).fill(minutes);
  await survey.getByRole('textbox', { name: /how many minutes/ }).press('Tab');
  // Questions on ideas the assignment's levels do not teach are not asked (survey-for-levels.ts).
  for (const name of [/ray tracing in general/, /kinds of light source/, /distance and angle/, /soft shadows/, /supersampling/, /ways of showing rays/]) {
    const group = survey.getByRole('group', { name });
    if ((await group.count()) > 0) await group.getByRole('radio', { name: '5, Helped a lot' }).check();
  }
  await survey.getByRole('radio', { name: 'About right' }).check();
  await survey.getByRole('textbox', { name: /other feedback/ }).fill('Nice, "really"\nthanks');
}

/** Clicks one of the export menu's buttons and returns the downloaded file's name and text. */
export async function download(page: Page, button: string): Promise<{ name: string; text: string }> {
  const started = page.waitForEvent('download');
  await page.locator('rt-export-menu').getByRole('button', { name: button }).click();
  const file = await started;
  return { name: file.suggestedFilename(), text: await readFile(await file.path(), 'utf8') };
}
