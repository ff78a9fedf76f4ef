import { expect, test, type Page } from '@playwright/test';
import { readFileSync } from 'node:fs';
import { encodeAssignment } from '../src/classroom/assignment-link.ts';
import { readDutchCatalogue } from '../tests/support/dutch-catalogue.ts';
import { collectErrors, current, levelsFolder } from './support/game-steps.ts';
import { simulatedClassFiles } from '../tests/support/class-exports.ts';

// Level 1 played in Dutch (?lang=nl), task by task with its hints and "Laat zien", up to a
// finished render: at every step, no word the page shows may be an English word of the UI's
// catalogue that Dutch does not use too. The page's text is read as the learner meets it:
// visible text inside every shadow root, and the labels and tooltips (aria-label, title,
// placeholder) that screen readers and the pointer reveal.

const catalogue = readDutchCatalogue();

/** A text's words: letters only, lower case ("Render image" → render, image). */
const words = (text: string) => text.toLowerCase().match(/\p{L}+/gu) ?? [];

/** Every Dutch string of a level file (texts and names). */
function dutchOfLevel(value: unknown): string[] {
  if (Array.isArray(value)) return value.flatMap(dutchOfLevel);
  if (typeof value !== 'object' || value === null) return [];
  return Object.entries(value).flatMap(([key, item]) => (key === 'nl' && typeof item === 'string' ? [item] : dutchOfLevel(item)));
}

const levelFiles = JSON.parse(readFileSync(new URL('index.json', levelsFolder), 'utf8')) as { chapters: { levels: string[] }[] };
const dutchLevelTexts = levelFiles.chapters
  .flatMap((chapter) => chapter.levels)
  .flatMap((id) => dutchOfLevel(JSON.parse(readFileSync(new URL(`${id}.level.json`, levelsFolder), 'utf8'))));

/** A text without what it quotes: a Dutch reason may quote a field path ("scene.settings.shadows"), which is no Dutch word. */
const prose = (text: string) => text.replace(/"[^"]*"/g, ' ');
/** A text without web addresses: a field's example (https://school.example) is in no language. */
const withoutAddresses = (text: string) => text.replace(/\bhttps?:\/\/\S+/g, ' ');

/**
 * Words Dutch uses too (in the Dutch catalogue or a Dutch level text): "lens", "pixel", "ray
 * tracer"; and each language's own name, which a language choice shows as it is in any
 * language ("English" beside "Nederlands" on the teacher page).
 */
const LANGUAGE_NAMES = 'English Nederlands';
const dutchWords = new Set([...catalogue.flatMap((message) => message.nl.map(prose)), ...dutchLevelTexts, LANGUAGE_NAMES].flatMap(words));
/** The English-only words of the UI: what may not show in Dutch. */
const englishOnly = new Set(
  catalogue
    .flatMap((message) => message.en)
    .flatMap(words)
    .filter((word) => !dutchWords.has(word)),
);

/** What the learner can read or hear: visible text nodes and the labels of elements, in and under every shadow root. */
async function shownTexts(page: Page): Promise<string[]> {
  return page.evaluate(() => {
    const found: string[] = [];
    const visit = (root: Document | ShadowRoot) => {
      const walker = document.createTreeWalker(root, NodeFilter.SHOW_ELEMENT | NodeFilter.SHOW_TEXT);
      for (let node = walker.nextNode(); node; node = walker.nextNode()) {
        if (node instanceof Text) {
          const parent = node.parentElement;
          if (parent && !['STYLE', 'SCRIPT'].includes(parent.tagName) && parent.checkVisibility() && node.data.trim()) found.push(node.data.trim());
        } else if (node instanceof Element) {
          if (node.checkVisibility())
            for (const name of ['aria-label', 'title', 'placeholder', 'alt']) if (node.getAttribute(name)) found.push(node.getAttribute(name) ?? '');
          if (node.shadowRoot) visit(node.shadowRoot);
        }
      }
    };
    visit(document);
    return found;
  });
}

/** Each shown text that has an English-only word, with the words. */
async function englishShown(page: Page): Promise<string[]> {
  return (await shownTexts(page)).flatMap((text) => {
    const english = words(withoutAddresses(text)).filter((word) => englishOnly.has(word));
    return english.length > 0 ? [`${english.join(', ')} in "${text.slice(0, 120)}"`] : [];
  });
}

async function expectNoEnglish(page: Page, where: string): Promise<void> {
  expect(await englishShown(page), where).toEqual([]);
}

test('the English-only words are found, and Dutch words are not among them', () => {
  for (const word of ['image', 'shadows', 'the', 'select']) expect(englishOnly.has(word), word).toBe(true);
  for (const word of ['lamp', 'pixel', 'bal', 'scène', 'renderen']) expect(englishOnly.has(word), word).toBe(false);
});

test('level 1 in Dutch shows no English, from the first task to a finished render', async ({ page }) => {
  test.setTimeout(180_000);
  const errors = collectErrors(page);
  await page.goto('./?lang=nl');
  await expect(page.locator('html')).toHaveAttribute('lang', 'nl');
  await expect(page.getByRole('heading', { name: 'Introductie' })).toBeVisible();
  await expectNoEnglish(page, 'the lab at the start');
  await page.screenshot({ path: 'test-results/dutch-level-1.png' });

  // Every task: its hints, the ring, then "Laat zien", which does it (visibly, 0 points).
  const level1 = JSON.parse(readFileSync(new URL('01-introduction.level.json', levelsFolder), 'utf8')) as { tasks: { mandatory?: boolean }[] };
  const mandatory = level1.tasks.filter((task) => task.mandatory !== false).length;
  for (let step = 0; step < mandatory; step++) {
    const card = current(page);
    const title = ((await card.textContent()) ?? '').trim().slice(0, 40);
    // The ladder: Hint, Nog een hint… until "Laat zien waar" is offered.
    const where = card.getByRole('button', { name: 'Laat zien waar' });
    const firstHint = card.getByRole('button', { name: 'Hint', exact: true });
    const anotherHint = card.getByRole('button', { name: 'Nog een hint', exact: true });
    for (let rung = 0; rung < 10 && !(await where.isVisible()); rung++) {
      if (await firstHint.isVisible()) await firstHint.click();
      else if (await anotherHint.isVisible()) await anotherHint.click();
      await page.waitForTimeout(500);
    }
    await expect(where).toBeVisible();
    await where.click();
    const showMe = card.getByRole('button', { name: 'Laat zien', exact: true });
    await expect(showMe).toBeVisible();
    await expectNoEnglish(page, `task ${step} (${title}) with its hints`);
    await showMe.click();
    await expect(page.getByText(title.slice(0, 12)).first()).toBeVisible();
    await page.waitForTimeout(300);
  }

  // The render window (the last task opened it): render, then read the figures.
  const render = page.getByRole('button', { name: 'Renderen', exact: true });
  if (!(await render.isVisible())) await page.getByRole('button', { name: 'Beeld renderen' }).click();
  await render.click();
  await expect(page.getByText(/Klaar in/)).toBeVisible({ timeout: 120_000 });
  await expectNoEnglish(page, 'the render window after a render');
  await page.screenshot({ path: 'test-results/dutch-level-1-render.png' });
  expect(errors).toEqual([]);
});

test('a later level in Dutch, opened from a Dutch assignment, shows no English', async ({ page }) => {
  const hash = await encodeAssignment({
    version: 1,
    title: 'Breking',
    levels: ['06-refraction'],
    requiredTasks: {},
    otherLevels: 'hidden',
    locale: 'nl',
    askParticipantCode: false,
    survey: null,
  });
  await page.goto(`./${hash}`);
  await expect(page.getByRole('heading', { name: 'Breking' }).first()).toBeVisible();
  await expectNoEnglish(page, 'level 6');
  await page.screenshot({ path: 'test-results/dutch-level-6.png' });
});

/**
 * Opens `route` in Dutch and runs `check` (what the page must show); then the page may show
 * no English and have logged no error, and its screenshot is kept as test-results/dutch-<name>.png.
 */
async function checkDutchPage(page: Page, route: string, name: string, check: () => Promise<void>): Promise<void> {
  const errors = collectErrors(page);
  await page.goto(`./?lang=nl${route}`);
  await check();
  await expectNoEnglish(page, `the ${name} page`);
  await page.screenshot({ path: `test-results/dutch-${name}.png`, fullPage: true });
  expect(errors).toEqual([]);
}

test('the free lab in Dutch names its scene and objects in Dutch and shows no English', async ({ page }) => {
  await checkDutchPage(page, '#free-lab', 'free-lab', async () => {
    const list = page.locator('rt-scene-list');
    await expect(list.getByRole('option', { name: /Rode bal/ })).toBeVisible({ timeout: 60_000 });
    await list.getByRole('option', { name: /Rode bal/ }).click();
  });
});

test('the teacher page in Dutch makes a Dutch assignment by default and shows no English', async ({ page }) => {
  await checkDutchPage(page, '#/teacher', 'teacher', async () => {
    const teacher = page.locator('rt-teacher-page');
    await expect(teacher.getByRole('radio', { name: 'Nederlands' })).toBeChecked();
    // The levels and their tasks in the pupils' language, as they will see them.
    await expect(teacher.locator('li[data-level]').first()).toContainText('Introductie');
  });
});

test("the teacher's survey preview in Dutch asks its questions in Dutch", async ({ page }) => {
  await checkDutchPage(page, '#/survey/default', 'survey', async () => {
    await expect(page.locator('rt-survey').getByRole('group').first()).toBeVisible();
  });
});

test('the class dashboard in Dutch names the levels and tasks in Dutch and shows no English', async ({ page }) => {
  await checkDutchPage(page, '#/dashboard', 'dashboard', async () => {
    const dashboard = page.locator('rt-dashboard-page');
    await dashboard
      .locator('input[type=file]')
      .setInputFiles(simulatedClassFiles(6).map((file) => ({ name: file.name, mimeType: 'application/json', buffer: Buffer.from(file.text) })));
    await expect(dashboard.getByRole('status').filter({ hasText: '6 leerlingen geteld' })).toBeVisible();
    await expect(dashboard.getByRole('heading', { name: 'Introductie' })).toBeVisible();
  });
});
