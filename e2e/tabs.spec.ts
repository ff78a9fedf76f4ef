import { expect, test, type Page } from '@playwright/test';
import { readFile } from 'node:fs/promises';
import { clickToolbar, collectErrors, current, expectStatus } from './support/game-steps.ts';

// Students open the game twice all the time. Five tabs of one browser play at once: what
// each does reaches the others (they show it) and the saved progress, and the JSON export
// holds every event of every tab.

interface ExportedEvent {
  id?: string;
  type: string;
}

async function openGame(page: Page): Promise<void> {
  await page.goto('./');
  const welcome = page.getByRole('button', { name: 'Got it' });
  await expect(current(page)).toBeVisible();
  if (await welcome.isVisible()) await welcome.click();
}

/** The event log of the tab's JSON export, as the learner downloads it. */
async function exportedEvents(page: Page): Promise<ExportedEvent[]> {
  const started = page.waitForEvent('download');
  await page.locator('rt-export-menu').getByRole('button', { name: 'Download results file' }).click();
  const file = await started;
  const exported = JSON.parse(await readFile(await file.path(), 'utf8')) as { events: { events: ExportedEvent[] } };
  return exported.events.events;
}

test("five tabs play at once: each shows the others' work and the export holds every tab's events", async ({ context }) => {
  const tabs: Page[] = [];
  const errors: string[][] = [];
  for (let i = 0; i < 5; i++) {
    const page = await context.newPage();
    errors.push(collectErrors(page));
    await openGame(page);
    tabs.push(page);
  }
  const [first, ...others] = tabs;

  // The first tab does two tasks; every other tab shows them done without a reload.
  await first.bringToFront();
  await clickToolbar(first, 'orbit-left');
  await expectStatus(first, 'Look around', 'done');
  await clickToolbar(first, 'zoom-in');
  await expectStatus(first, 'Zoom in', 'done');
  for (const page of others) {
    await expectStatus(page, 'Look around', 'done');
    await expectStatus(page, 'Zoom in', 'done');
  }

  // The four others each ask for a hint on the task they are now at.
  for (const page of others) {
    await page.bringToFront();
    await expect(current(page)).toContainText('Select the ball');
    await current(page).getByRole('button', { name: 'Hint' }).click();
  }

  // Every event each tab logged (its own export holds them) ends up in the first tab's export.
  const perTab = [];
  for (const page of tabs) perTab.push((await exportedEvents(page)).map((event) => event.id));
  const everyId = new Set(perTab.flat());
  expect(perTab.flat().every((id) => id !== undefined)).toBe(true);
  await expect
    .poll(async () => {
      const exported = new Set((await exportedEvents(first)).map((event) => event.id));
      return [...everyId].filter((id) => !exported.has(id));
    })
    .toEqual([]);
  const final = await exportedEvents(first);
  expect(final.filter((event) => event.type === 'session.started')).toHaveLength(5);
  expect(final.filter((event) => event.type === 'hint.shown')).toHaveLength(4);
  expect(final.filter((event) => event.type === 'task.completed')).toHaveLength(2);

  // A sixth tab, opened afterwards, sees all of it.
  const sixth = await context.newPage();
  await openGame(sixth);
  await expectStatus(sixth, 'Look around', 'done');
  await expectStatus(sixth, 'Zoom in', 'done');
  expect(errors.flat()).toEqual([]);
});
