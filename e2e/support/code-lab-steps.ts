import { readdirSync } from 'node:fs';
import type { Locator, Page } from '@playwright/test';
import { levelsFolder, progressFile } from './game-steps.ts';

// The steps every code lab spec takes: a saved progress in which the lab's level is open, the
// level opened from the map, its code task opened, code typed into the editor, and what the 3D
// view draws of the failing case.

/** A correct ray–sphere test (Shirley & Marschner §4.4.1) as a learner writes it: the nearest t > 0, or null. */
export const CORRECT_HIT_SPHERE = `function hitSphere(origin, direction, center, radius) {
  const oc = sub(origin, center);
  const a = dot(direction, direction);
  const b = 2 * dot(oc, direction);
  const c = dot(oc, oc) - radius * radius;
  const d = b * b - 4 * a * c;
  if (d < 0) return null;
  const near = (-b - Math.sqrt(d)) / (2 * a);
  if (near > 0) return near;
  const far = (-b + Math.sqrt(d)) / (2 * a);
  return far > 0 ? far : null;
}`;

/** Every level but `level` passed, so that it is open. */
export const allPassedBut = (level: string) =>
  progressFile(
    readdirSync(levelsFolder)
      .filter((name) => name.endsWith('.level.json'))
      .map((name) => name.replace('.level.json', ''))
      .filter((id) => id !== level),
  );

/**
 * Starts the app at `url` with `progress` saved, opens `level` from the map and its code task
 * `taskId`; returns the task's code lab. Init scripts run in every frame: the sandbox's has no
 * storage at all, so only the top frame seeds, once.
 */
export async function openCodeTask(page: Page, progress: string, level: string, taskId: string, url = '/'): Promise<Locator> {
  await page.addInitScript((saved) => {
    if (window !== window.top || sessionStorage.getItem('seeded')) return;
    sessionStorage.setItem('seeded', 'yes');
    localStorage.setItem('rtq.progress', saved);
  }, progress);
  await page.goto(url);
  return openCodeTaskHere(page, level, taskId);
}

/** Opens `level` from the map of the page as it is now, and its code task `taskId`; returns the task's code lab. */
export async function openCodeTaskHere(page: Page, level: string, taskId: string): Promise<Locator> {
  const welcome = page.getByRole('button', { name: 'Got it' });
  if (await welcome.count()) await welcome.click();
  await page.locator('[data-command="levels"]').click();
  await page.locator(`rt-level-map [data-level="${level}"]`).click();
  await page.locator(`rt-task-card[data-task="${taskId}"] button.head`).click();
  return page.locator('rt-code-lab');
}

/** Replaces the editor's whole text with `code`, as a learner pasting it. */
export async function typeCode(page: Page, code: string): Promise<void> {
  await page.locator('rt-code-lab .cm-content').click();
  await page.keyboard.press('ControlOrMeta+a');
  await page.keyboard.insertText(code);
}

type ShownCase = { points: { mark: string }[]; shapes: { kind: string }[] } | null;

/** The failing case the 3D view draws now (null: none), through the view's declared test probe. */
export const shownCase = (page: Page) =>
  page.locator('rt-scene-view').evaluate((element) => (element as unknown as { labView: { labCase: { shown: ShownCase } } }).labView.labCase.shown);
