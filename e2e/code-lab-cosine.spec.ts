import { expect, test } from '@playwright/test';
import { readFileSync } from 'node:fs';
import { expectAccessible } from './support/axe.ts';
import { openCodeTask, shownCase, typeCode } from './support/code-lab-steps.ts';
import { collectErrors, expectStatus, levelsFolder, progressFile } from './support/game-steps.ts';

// The path chapter's code lab (level 23): a random function graded as a sample in the browser's
// sandbox, 4004 runs within the time limit. A whole-sphere function is stopped on its first
// direction into the surface, drawn in 3D; Malley's method passes and completes the task.

const index = JSON.parse(readFileSync(new URL('index.json', levelsFolder), 'utf8')) as { chapters: { levels: string[] }[] };
const order = index.chapters.flatMap((chapter) => chapter.levels);
const LEVEL = '23-better-guesses';
const TITLE = 'Code lab: cosine bounces';

const MALLEY = `function cosineDirection(normal, random) {
  const r = Math.sqrt(random()), phi = 2 * Math.PI * random();
  const x = r * Math.cos(phi), y = r * Math.sin(phi), z = Math.sqrt(1 - r * r);
  const helper = Math.abs(normal.x) > 0.9 ? vec(0, 1, 0) : vec(1, 0, 0);
  const t = normalize(cross(helper, normal));
  const b = cross(normal, t);
  return add(add(scale(t, x), scale(b, y)), scale(normal, z));
}`;

const WHOLE_SPHERE = `function cosineDirection(normal, random) {
  const z = 2 * random() - 1, r = Math.sqrt(1 - z * z), phi = 2 * Math.PI * random();
  return vec(r * Math.cos(phi), r * Math.sin(phi), z);
}`;

test('the cosine-bounce lab grades a sample of directions and draws a failing one', async ({ page }) => {
  const errors = collectErrors(page);
  const lab = await openCodeTask(page, progressFile(order.slice(0, order.indexOf(LEVEL))), LEVEL, 'code-cosine-bounce');
  const run = lab.getByRole('button', { name: 'Run tests' });
  const result = lab.getByRole('status');

  await typeCode(page, WHOLE_SPHERE);
  await run.click();
  await expect(result).toContainText('which goes into the surface');
  await expect(result).toContainText('Drawn in the 3D view, turned so that the normal points up: the normal and the cosine lobe');
  const drawn = await shownCase(page);
  expect(drawn?.shapes).toEqual([expect.objectContaining({ kind: 'sphere' })]);
  expect(drawn?.points.filter((point) => point.mark === 'got').length).toBeGreaterThan(10);
  await expectAccessible(page, 'the cosine-bounce lab with a failing run');

  await typeCode(page, MALLEY);
  await run.click();
  await expect(result).toContainText('4004 runs: every direction of length 1, on the normal’s side, the same for the same random.');
  expect(await shownCase(page)).toBeNull();
  await expectStatus(page, TITLE, 'done');
  expect(errors).toEqual([]);
});

// Render with my function in the cosine lab: a path render of level 23 whose bounces take the
// learner's directions, beside the tracer's. Noisy, so the pictures' mean brightness is
// compared, not their pixels: Malley's method comes within the noise, uniform directions
// weighted as cosine ones come out darker (docs/code-labs.md has the figures).

const UNIFORM = MALLEY.replace('const r = Math.sqrt(random())', 'const r = Math.sqrt(1 - (1 - random()) ** 2)');

test('Render with my function in the cosine lab shows both pictures and compares their mean brightness', async ({ page }) => {
  const errors = collectErrors(page);
  const lab = await openCodeTask(page, progressFile(order.slice(0, order.indexOf(LEVEL))), LEVEL, 'code-cosine-bounce');
  const renderButton = lab.getByRole('button', { name: 'Render with my function' });
  const brightness = lab.getByText(/^Mean brightness: your picture (\d\.\d{3}), the tracer’s (\d\.\d{3})\./);
  const mine = lab.getByRole('img', { name: 'The level’s scene rendered with your function.' });

  await typeCode(page, MALLEY);
  await renderButton.click();
  await expect(brightness).toContainText('as close as two noisy renders of the same density come', { timeout: 30_000 });
  expect(await mine.evaluate((canvas) => [(canvas as HTMLCanvasElement).width, (canvas as HTMLCanvasElement).height])).toEqual([64, 64]);
  await expect(lab.getByRole('img', { name: /^The difference between the two pictures/ })).toHaveCount(0);
  await expectAccessible(page, 'the cosine lab with its pictures');

  await typeCode(page, UNIFORM);
  await renderButton.click();
  await expect(brightness).toContainText('darker, more than the noise explains', { timeout: 30_000 });
  const [, yours, tracers] = /your picture (\d\.\d{3}), the tracer’s (\d\.\d{3})/.exec((await brightness.textContent())!)!;
  expect(Number(yours)).toBeLessThan(0.95 * Number(tracers));
  expect(errors).toEqual([]);
});
