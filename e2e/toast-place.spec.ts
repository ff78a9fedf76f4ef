import { expect, test } from '@playwright/test';
import { readFileSync } from 'node:fs';
import { current, importProgress, levelsFolder, panel, progressFile } from './support/game-steps.ts';

// A message at a level's start (src/ui/lab/toast-place.ts) covers neither the title and intro
// the learner reads first nor the current task. Level 21 at 1366×768: its first task's middle
// is below the screen's middle, which sent messages to the column's top, over the intro.

const index = JSON.parse(readFileSync(new URL('index.json', levelsFolder), 'utf8')) as { chapters: { levels: string[] }[] };
const levelIds = index.chapters.flatMap((chapter) => chapter.levels);

test("a message at a level's start leaves its intro and current task uncovered", async ({ page }) => {
  await page.goto('./');
  await page.getByRole('button', { name: 'Got it' }).click();
  await importProgress(page, progressFile(levelIds.slice(0, levelIds.indexOf('21-light-that-bounces'))));
  if (!(await page.locator('rt-level-map').isVisible())) await page.locator('[data-command="levels"]').click();
  await page.locator('rt-level-map [data-level="21-light-that-bounces"]').click();
  await expect(current(page)).toHaveAttribute('data-task', 'render-whitted');
  await page
    .locator('rt-lab')
    .evaluate((lab: HTMLElement & { toast(text: string): void }) =>
      lab.toast('The render window was closed to show the 3D view this task needs. Open it again with Render image.'),
    );
  const message = (await page.locator('rt-toast .toast').last().boundingBox())!;
  for (const kept of [panel(page).locator('header'), current(page)]) {
    const box = (await kept.boundingBox())!;
    const apart =
      box.y + box.height <= message.y || message.y + message.height <= box.y || box.x + box.width <= message.x || message.x + message.width <= box.x;
    expect(apart, JSON.stringify({ box, message })).toBe(true);
  }
});
