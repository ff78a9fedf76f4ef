import { expect, test, type Page } from '@playwright/test';
import { mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { goalSchema, kindOfGoal } from '../src/quest/goal.ts';
import { LAB_CONTROLS, type LabPanel } from '../src/quest/lab-controls.ts';
import type { DeclaredView } from '../src/lab-state/lab-action.ts';
import type { TaskEvidence } from '../src/quest/task-evidence-schema.ts';
import { expectEvidenceShows, type EvidenceFigures } from './support/evidence-checks.ts';
import { collectErrors, current, importProgress, levelsFolder, panel, progressFile } from './support/game-steps.ts';
import { expectViewShows, viewAtStart, viewSettled } from './support/view-checks.ts';

// Every level, played task by task through the hint ladder as a stuck student would: for
// each task the ring goes to a control (or a point of the 3D view) that is on screen, and
// every control the level leaves out of a panel is not on the page at all. A task that
// declares a view starts in it, with what the view frames on screen and its pixel's rays
// readable. A task that declares its evidence (the rays and things its text names) shows
// them at its start view, large enough and under no panel (support/evidence-checks.ts).
// One browser run per level; each task's start view is saved under test-results/task-views/,
// with the evidence's figures in <level>--evidence.json.

interface LevelTask {
  id: string;
  guide?: string;
  mandatory?: boolean;
  goal: Record<string, unknown>;
  view?: DeclaredView;
  evidence?: TaskEvidence;
}
interface LevelFile {
  id: string;
  view?: DeclaredView;
  ui: { panels: string[]; controls?: Partial<Record<LabPanel, string[]>> };
  tasks: LevelTask[];
}

const index = JSON.parse(readFileSync(new URL('index.json', levelsFolder), 'utf8')) as { chapters: { levels: string[] }[] };
const levelIds = index.chapters.flatMap((chapter) => chapter.levels);
const readLevel = (id: string) => JSON.parse(readFileSync(new URL(`${id}.level.json`, levelsFolder), 'utf8')) as LevelFile;
const VIEWPORT = { width: 1366, height: 768 };

/** The lab's public guide API: where the ring would go for a target, and the elements that carry it. */
function lab(page: Page) {
  return page.locator('rt-lab');
}

async function guideBox(page: Page, target: string) {
  return lab(page).evaluate(
    (element, id) => (element as unknown as { guideRect(id: string): { left: number; top: number; width: number; height: number } | null }).guideRect(id),
    target,
  );
}

async function guideCount(page: Page, target: string): Promise<number> {
  return lab(page).evaluate((element, id) => (element as unknown as { guideElements(id: string): Element[] }).guideElements(id).length, target);
}

/** The controls a level narrows its panels away from are not rendered, whatever is selected. */
async function expectHiddenControlsAbsent(page: Page, level: LevelFile): Promise<void> {
  for (const [panelName, shown] of Object.entries(level.ui.controls ?? {}) as [LabPanel, string[]][]) {
    for (const control of LAB_CONTROLS[panelName].filter((id) => !shown.includes(id))) {
      expect(await guideCount(page, `${panelName}.${control}`), `${level.id}: ${panelName}.${control} is hidden`).toBe(0);
    }
  }
}

/** The ring's target is on screen: inside the viewport, with some size, and the ring is drawn around it. */
async function expectGuideOnScreen(page: Page, levelId: string, task: LevelTask): Promise<void> {
  const target = task.guide!;
  await expect.poll(() => guideBox(page, target), { message: `${levelId}/${task.id}: ${target} has a place on screen` }).not.toBeNull();
  const box = (await guideBox(page, target))!;
  expect(box.width, `${levelId}/${task.id}: ${target} has a width`).toBeGreaterThan(4);
  expect(box.left + box.width / 2, `${levelId}/${task.id}: ${target} inside the window`).toBeGreaterThan(0);
  expect(box.left + box.width / 2).toBeLessThan(VIEWPORT.width);
  expect(box.top + box.height / 2).toBeGreaterThan(0);
  expect(box.top + box.height / 2).toBeLessThan(VIEWPORT.height);
  const ring = await page.getByTestId('guide-ring').boundingBox();
  expect(ring, `${levelId}/${task.id}: the ring is drawn`).not.toBeNull();
  expect(Math.abs(ring!.x + ring!.width / 2 - (box.left + box.width / 2)), `${levelId}/${task.id}: the ring is around ${target}`).toBeLessThan(12);
  await expectHitWhereRingPoints(page, `${levelId}/${task.id}`, target, { x: ring!.x + ring!.width / 2, y: ring!.y + ring!.height / 2 });
}

/**
 * What a learner would click where the ring points is the guide's target: a control that
 * carries its id (under the pointer, nothing on top of it), or in the 3D view the pixel it names.
 */
async function expectHitWhereRingPoints(page: Page, where: string, target: string, centre: { x: number; y: number }): Promise<void> {
  // A control's elements (a group such as columns and rows has several): each one, at its middle, is what the pointer is over.
  const carriers = await lab(page).evaluate((element, id) => {
    const boxes = (element as unknown as { guideElements(id: string): Element[] }).guideElements(id).map((carrier) => carrier.getBoundingClientRect());
    return boxes.filter((box) => box.width > 0).map((box) => ({ x: box.left + box.width / 2, y: box.top + box.height / 2 }));
  }, target);
  for (const [index, point] of carriers.entries()) {
    await page.mouse.move(point.x, point.y);
    const over = await lab(page).evaluate(
      (element, [id, at]) =>
        (element as unknown as { guideElements(id: string): Element[] })
          .guideElements(id)
          .filter((carrier) => carrier.getBoundingClientRect().width > 0)
          .at(at)
          ?.matches(':hover') ?? false,
      [target, index] as const,
    );
    expect(over, `${where}: the pointer on ${target} (part ${index + 1} of ${carriers.length}) is over it, not over something on top`).toBe(true);
  }
  if (carriers.length > 0) return;
  await page.mouse.move(centre.x, centre.y);
  // An object in the 3D view is checked for its place only: a task may ask to find one that
  // something hides (level 14's ball behind the wall), so a click there rightly picks the wall.
  const pixel = /^screen\.pixel:(\d+),(\d+)$/.exec(target);
  if (!pixel) return; // or a control reached through another (its panel's note) until it is shown
  const picked = await page
    .locator('rt-scene-view')
    .evaluate((element, point) => (element as unknown as { labView: { pickAt(x: number, y: number): unknown } }).labView.pickAt(point.x, point.y), centre);
  expect(picked, `${where}: a click where the ring points picks pixel ${pixel![1]},${pixel![2]}`).toEqual({
    kind: 'pixel',
    pixel: [Number(pixel![1]), Number(pixel![2])],
  });
}

/** Climbs the current task's hint ladder to "Show me", checking the ring on the way, then lets the app do the task. */
async function solveCurrentTask(page: Page, level: LevelFile, task: LevelTask): Promise<void> {
  const card = current(page);
  if (kindOfGoal(goalSchema.parse(task.goal)) === 'info') {
    await card.getByRole('button', { name: 'Next' }).click();
    return;
  }
  for (let step = 0; step < 6; step++) {
    const button = card.locator('rt-hint-box button[data-hint]');
    const kind = await button.getAttribute('data-hint');
    await button.click();
    if (kind === 'guidance' && task.guide) await expectGuideOnScreen(page, level.id, task);
    if (kind === 'show-me') return;
  }
  throw new Error(`${level.id}/${task.id}: the hint ladder never reached "Show me"`);
}

for (const [position, levelId] of levelIds.entries()) {
  test(`${levelId}: every task's ring is on screen, and hidden controls are absent`, async ({ page }) => {
    const level = readLevel(levelId);
    test.setTimeout(60_000 + level.tasks.length * 20_000);
    mkdirSync('test-results/task-views', { recursive: true });
    const errors = collectErrors(page);
    await page.setViewportSize(VIEWPORT);
    await page.goto('./');
    await page.getByRole('button', { name: 'Got it' }).click();
    await importProgress(page, progressFile(levelIds.slice(0, position)));
    if (!(await page.locator('rt-level-map').isVisible())) await page.locator('[data-command="levels"]').click();
    await page.locator(`rt-level-map [data-level="${levelId}"]`).click();
    await expect(panel(page).locator('h2')).toBeVisible();

    const visited: string[] = [];
    const figures: ({ task: string } & EvidenceFigures)[] = [];
    while (!(await panel(page).getByText('Level complete!').isVisible())) {
      const id = await current(page).getAttribute('data-task', { timeout: 30_000 });
      const task = level.tasks.find((candidate) => candidate.id === id);
      expect(task, `${levelId}: the current task ${id} is in the file`).toBeDefined();
      expect(visited, `${levelId}: ${id} comes up once`).not.toContain(id);
      visited.push(id!);
      const view = viewAtStart(level, task!, visited.length === 1);
      if (view) await viewSettled(page, `${levelId}/${id}`);
      else await page.waitForTimeout(300);
      await page.screenshot({ path: `test-results/task-views/${levelId}--${id}.png` });
      if (view) await expectViewShows(page, `${levelId}/${id}`, view);
      if (task!.evidence) figures.push({ task: id!, ...(await expectEvidenceShows(page, `${levelId}/${id}`, task!.evidence)) });
      await expectHiddenControlsAbsent(page, level);
      await solveCurrentTask(page, level, task!);
      await expect(page.locator(`rt-task-card[data-task="${id}"]`)).not.toHaveAttribute('status', 'current', { timeout: 30_000 });
    }
    if (figures.length > 0) writeFileSync(`test-results/task-views/${levelId}--evidence.json`, `${JSON.stringify(figures, null, 1)}\n`);
    const mandatory = level.tasks.filter((task) => task.mandatory !== false).map((task) => task.id);
    expect(visited).toEqual(mandatory);
    expect(errors).toEqual([]);
  });
}
