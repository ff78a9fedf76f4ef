import { readFile } from 'node:fs/promises';
import { expect, test, type FrameLocator, type Page } from '@playwright/test';
import { unzipSync } from 'fflate';
import type { Assignment } from '../src/classroom/assignment.ts';
import { collectErrors } from './support/game-steps.ts';
import { startScormHost, type ScormHost } from './support/scorm-host.ts';

// Issue 40's "done when": a SCORM package of an assignment, downloaded from the teacher
// page, played in a page hosted by an independent SCORM runtime (scorm-again), leaves
// completion, score and one interaction per task and quiz there. A pupil orbits the view
// (level 1's task) and answers level 2's prediction wrong; the runtime then holds the
// values; a relaunch in a fresh browser (nothing in its storage) with the runtime's suspend
// data resumes: the assignment is finished there too. Then the 1.2 package, played by
// another pupil in the first browser: they start afresh and 1.2's values arrive.

const assignment: Assignment = {
  version: 1,
  title: 'Licht & stralen',
  levels: ['01-introduction', '02-rays-from-the-camera'],
  requiredTasks: { '01-introduction': ['orbit'], '02-rays-from-the-camera': ['predict-light-path'] },
  otherLevels: 'hidden',
  locale: 'en',
  askParticipantCode: false,
  survey: null,
};

type Cmi = Record<string, string>;

async function downloadPackage(page: Page, button: string): Promise<Record<string, Uint8Array>> {
  await page.goto('./#/teacher');
  const teacher = page.locator('rt-teacher-page');
  // The form is the teacher page's own test's (classroom.spec.ts): here the assignment is set as the form would.
  await teacher.evaluate((element, value) => Object.assign(element, { assignment: value }), assignment);
  const scorm = teacher.locator('rt-scorm-download');
  await expect(scorm.getByRole('button', { name: button })).toBeEnabled();
  const [download] = await Promise.all([page.waitForEvent('download'), scorm.getByRole('button', { name: button }).click()]);
  await expect(scorm.getByRole('status')).toContainText('The package is downloaded');
  return unzipSync(new Uint8Array(await readFile((await download.path())!)));
}

/** The manifest read by Chromium's strict XML parser: the SCO's launch address (resource href and item parameters). */
async function launchOf(page: Page, manifest: Uint8Array, version: '1.2' | '2004'): Promise<string> {
  const read = await page.evaluate((text) => {
    const document = new DOMParser().parseFromString(text, 'application/xml');
    const item = document.querySelector('item');
    const resource = document.querySelector(`resource[identifier="${item?.getAttribute('identifierref')}"]`);
    return {
      errors: document.getElementsByTagName('parsererror').length,
      href: resource?.getAttribute('href'),
      parameters: item?.getAttribute('parameters'),
      version: document.querySelector('schemaversion')?.textContent,
    };
  }, new TextDecoder().decode(manifest));
  expect(read).toMatchObject({ errors: 0, href: 'index.html', version: version === '2004' ? '2004 4th Edition' : '1.2' });
  return `scorm-${version}/${read.href}${read.parameters}`;
}

/** A newcomer's welcome (shown when the browser had no progress), level 1's required task (orbit), then level 2's prediction, answered wrong. */
async function playTheAssignment(frame: FrameLocator, welcome: boolean): Promise<void> {
  if (welcome) await frame.getByRole('button', { name: 'Got it' }).click();
  await frame.locator('rt-view-toolbar [data-command="orbit-left"]').click();
  await frame.locator('rt-quest-panel').getByRole('button', { name: 'Next level' }).click();
  const quiz = frame.locator('rt-task-card[status="current"]');
  await quiz.getByRole('radio', { name: 'It sends rays from the lamp in every direction', exact: true }).check();
  await quiz.getByRole('button', { name: 'Lock in my prediction' }).click();
}

const game = (page: Page): FrameLocator => page.frameLocator('iframe[title="Activity"]');
const runtimeValues = (page: Page): Promise<Cmi> =>
  page.evaluate(() => (window as unknown as { runtime: { getFlattenedCMI(): Cmi } }).runtime.getFlattenedCMI());

test('SCORM 2004 and 1.2 packages report to scorm-again; 2004 resumes from its suspend data', async ({ page, browser }) => {
  const errors = collectErrors(page);
  const files = await downloadPackage(page, 'SCORM 2004 package');
  expect(files['index.html']).toBeDefined();
  const launch = await launchOf(page, files['imsmanifest.xml'], '2004');
  const files12 = await downloadPackage(page, 'SCORM 1.2 package');
  const launch12 = await launchOf(page, files12['imsmanifest.xml'], '1.2');
  let host: ScormHost | undefined;
  try {
    host = await startScormHost({ 'scorm-2004': files, 'scorm-1.2': files12 });
    const player = await page.context().newPage();
    const playerErrors = collectErrors(player);
    await player.goto(host.playerUrl({ version: '2004', cmi: { learner_id: 'pupil-7', learner_name: 'Pupil, Seven' }, launch }));
    await playTheAssignment(game(player), true);
    await expect.poll(async () => (await runtimeValues(player))['cmi.completion_status']).toBe('completed');
    // The pupil closes the activity: the game's last commit and Terminate.
    await player.evaluate(() => document.querySelector('iframe')!.remove());
    const cmi = await runtimeValues(player);
    expect(cmi).toMatchObject({
      'cmi.completion_status': 'completed',
      'cmi.success_status': 'passed',
      'cmi.score.raw': '10',
      'cmi.score.min': '0',
      'cmi.score.max': '20',
      'cmi.score.scaled': '0.5',
      // Suspend also when done: the next launch resumes instead of starting a new, incomplete attempt.
      'cmi.exit': 'suspend',
      'cmi.interactions.0.id': '01-introduction/orbit',
      'cmi.interactions.0.type': 'other',
      'cmi.interactions.0.learner_response': 'done',
      'cmi.interactions.0.result': 'correct',
      'cmi.interactions.1.id': '02-rays-from-the-camera/predict-light-path',
      'cmi.interactions.1.type': 'choice',
      'cmi.interactions.1.learner_response': 'd',
      'cmi.interactions.1.result': 'incorrect',
    });
    expect(cmi['cmi.interactions.2.id']).toBeUndefined();
    for (const n of [0, 1]) expect(cmi[`cmi.interactions.${n}.latency`]).toMatch(/^PT(\d+M)?\d+(\.\d+)?S$/);
    expect(cmi['cmi.session_time']).toMatch(/^PT/);
    expect(cmi['cmi.suspend_data']).toMatch(/^rtq1\./);
    expect(host.missing).toEqual([]);
    expect(playerErrors).toEqual([]);

    // Another computer: a fresh browser, the platform hands back what it kept.
    const other = await browser.newContext({ serviceWorkers: 'block', viewport: { width: 1366, height: 768 } });
    const again = await other.newPage();
    await again.goto(host.playerUrl({ version: '2004', cmi: { learner_id: 'pupil-7', entry: 'resume', suspend_data: cmi['cmi.suspend_data'] }, launch }));
    await expect(game(again).getByRole('heading', { name: 'Assignment finished' })).toBeVisible();
    await expect.poll(async () => (await runtimeValues(again))['cmi.completion_status']).toBe('completed');
    expect((await runtimeValues(again))['cmi.score.raw']).toBe('10');
    await other.close();

    // SCORM 1.2, on the computer the first pupil used: another pupil starts afresh (the platform says who plays).
    await player.goto(host.playerUrl({ version: '1.2', cmi: { core: { student_id: 'pupil-8', student_name: 'Pupil, Eight' } }, launch: launch12 }));
    // The first pupil's finished work is cleared: level 1 again (the game welcomed this browser before).
    await expect(game(player).locator('rt-quest-panel').getByRole('heading', { name: 'Introduction' })).toBeVisible();
    await playTheAssignment(game(player), false);
    await expect.poll(async () => (await runtimeValues(player))['cmi.core.lesson_status']).toBe('passed');
    await player.evaluate(() => document.querySelector('iframe')!.remove());
    expect(await runtimeValues(player)).toMatchObject({
      'cmi.core.lesson_status': 'passed',
      'cmi.core.score.raw': '50',
      'cmi.core.score.max': '100',
      'cmi.interactions.0.id': '01-introduction/orbit',
      'cmi.interactions.0.type': 'performance',
      'cmi.interactions.0.student_response': 'done',
      'cmi.interactions.0.result': 'correct',
      'cmi.interactions.1.id': '02-rays-from-the-camera/predict-light-path',
      'cmi.interactions.1.type': 'choice',
      'cmi.interactions.1.student_response': 'd',
      'cmi.interactions.1.result': 'wrong',
      'cmi.suspend_data': expect.stringMatching(/^rtq1\./),
    });
    expect(host.missing).toEqual([]);
    expect(playerErrors).toEqual([]);
  } finally {
    await host?.close();
  }
  expect(errors).toEqual([]);
});
