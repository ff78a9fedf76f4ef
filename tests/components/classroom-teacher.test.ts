// The teacher's side of the classroom: the teacher page's sections (what a teacher ticks and
// what the page then offers), its SCORM download, and the pupil's export menu that makes the
// files the teacher collects. Reached through what a user clicks and sees, and the files made.
import { unzipSync, strFromU8 } from 'fflate';
import { render } from 'lit';
import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import { page } from 'vitest/browser';
import type { Assignment } from '../../src/classroom/assignment.ts';
import { decodeResultsCode, RESULTS_CODE_PREFIX } from '../../src/classroom/results-code.ts';
import { newProgress } from '../../src/quest/progress.ts';
import '../../src/ui/classroom/rt-export-menu.ts';
import '../../src/ui/classroom/rt-scorm-download.ts';
import { afterLessonSection, settingsSection } from '../../src/ui/classroom/teacher-sections.ts';
import { CLASS_ASSIGNMENT } from '../support/class-exports.ts';
import { mount, unmountAll } from './mount.ts';

/** The blobs the page hands to the browser as downloads, with the names it gives them. */
function catchDownloads(): { name: string; blob: Blob }[] {
  const downloads: { name: string; blob: Blob }[] = [];
  const blobs = new Map<string, Blob>();
  const make = URL.createObjectURL.bind(URL);
  vi.spyOn(URL, 'createObjectURL').mockImplementation((blob) => {
    const url = make(blob);
    blobs.set(url, blob as Blob);
    return url;
  });
  vi.spyOn(HTMLAnchorElement.prototype, 'click').mockImplementation(function (this: HTMLAnchorElement) {
    downloads.push({ name: this.download, blob: blobs.get(this.href)! });
  });
  return downloads;
}

afterEach(() => {
  unmountAll();
  vi.restoreAllMocks();
});

describe("the teacher page's settings and after-lesson sections", () => {
  let host: HTMLElement;
  let assignment: Assignment;
  /** The page's loop: a section changes the assignment, the page draws it again. */
  const draw = () => render([settingsSection(assignment, change), afterLessonSection()], host);
  const change = (changes: Partial<Assignment>) => {
    assignment = { ...assignment, ...changes };
    draw();
  };

  beforeEach(() => {
    host = document.createElement('div');
    document.body.append(host);
    assignment = { ...CLASS_ASSIGNMENT, askParticipantCode: false };
    draw();
  });
  afterEach(() => host.remove());

  it('changes the settings the teacher clicks', async () => {
    const view = page.elementLocator(host);
    await view.getByRole('radio', { name: 'Ask for a code at the start (for research)' }).click();
    await view.getByRole('radio', { name: 'Nederlands' }).click();
    await view.getByRole('radio', { name: 'Shown: playable after the assignment' }).click();
    expect([assignment.askParticipantCode, assignment.locale, assignment.otherLevels]).toEqual([true, 'nl', 'shown']);
    await view.getByRole('radio', { name: 'None' }).click();
    expect(assignment.survey).toBeNull();
    // Without a survey there is nothing to preview or choose.
    await expect.element(view.getByRole('link', { name: /Preview the survey/ })).not.toBeInTheDocument();
    await expect.element(view.getByRole('group', { name: 'Survey questions to ask' })).not.toBeInTheDocument();
  });

  it("ticks the questions that fit the levels, keeps the teacher's own choice, and previews only the questions asked", async () => {
    const view = page.elementLocator(host);
    const attenuation = view.getByRole('checkbox', { name: /how light gets weaker/ });
    const minutes = view.getByRole('checkbox', { name: /About how many minutes/ });
    // Levels 1 and 2 teach no attenuation: not ticked, and said why.
    await expect.element(attenuation).not.toBeChecked();
    await expect.element(minutes).toBeChecked();
    await expect.element(view.getByRole('button', { name: 'Back to the questions that fit the levels' })).toBeDisabled();

    await minutes.click();
    await attenuation.click();
    expect(assignment.surveyQuestions).toEqual({ minutes: false, 'learned-attenuation': true });
    const preview = view
      .getByRole('link', { name: /Preview the survey/ })
      .element()
      .getAttribute('href')!;
    const asked = preview.slice('#/survey/default/'.length).split(',');
    expect(asked).toContain('learned-attenuation');
    expect(asked).not.toContain('minutes');
    expect(asked).not.toContain('learned-soft-shadows');

    await view.getByRole('button', { name: 'Back to the questions that fit the levels' }).click();
    expect(assignment.surveyQuestions).toBeUndefined();
    await expect.element(minutes).toBeChecked();
  });

  it('links to the dashboard for after the lesson', async () => {
    await expect.element(page.elementLocator(host).getByRole('link', { name: 'Open the dashboard' })).toHaveAttribute('href', '#/dashboard');
  });
});

describe('rt-scorm-download', () => {
  const link = `${location.origin}/#/a/1.abc`;

  it('offers no package while the assignment has no link', async () => {
    const download = await mount('rt-scorm-download', { link: null, assignmentTitle: 'Licht' });
    await expect.element(page.elementLocator(download).getByRole('button', { name: 'SCORM 2004 package' })).toBeDisabled();
    await expect.element(page.elementLocator(download).getByRole('button', { name: 'SCORM 1.2 package' })).toBeDisabled();
  });

  it('says so, and downloads nothing, when the page is not a built app on a web server', async () => {
    const downloads = catchDownloads();
    vi.spyOn(window, 'fetch').mockResolvedValue(new Response('not here', { status: 404 }));
    const download = await mount('rt-scorm-download', { link, assignmentTitle: 'Licht' });
    const view = page.elementLocator(download);
    await view.getByRole('button', { name: 'SCORM 1.2 package' }).click();
    await expect.element(view.getByRole('status')).toHaveTextContent('A package can only be made from the built app on a web server');
    expect(downloads).toEqual([]);
  });

  it("packs the build's files with a manifest for the chosen SCORM version, named after the assignment", async () => {
    const downloads = catchDownloads();
    const build: Record<string, string> = {
      'sw.js': 'precacheAndRoute([{url:"index.html",revision:"1"},{url:"assets/app.js",revision:"2"}])',
      'index.html': '<!doctype html><title>Ray Tracer Quest</title>',
      'assets/app.js': 'console.log("game")',
    };
    vi.spyOn(window, 'fetch').mockImplementation(async (input) => {
      const path = new URL(String(input)).pathname.slice(1);
      return path in build ? new Response(build[path]) : new Response('', { status: 404 });
    });
    const download = await mount('rt-scorm-download', { link, assignmentTitle: 'Licht en schaduw' });
    const view = page.elementLocator(download);
    await view.getByRole('button', { name: 'SCORM 2004 package' }).click();
    await expect.element(view.getByRole('status')).toHaveTextContent('The package is downloaded');
    expect(downloads.map((file) => file.name)).toEqual(['licht-en-schaduw-scorm-2004.zip']);
    const zip = unzipSync(new Uint8Array(await downloads[0]!.blob.arrayBuffer()));
    expect(Object.keys(zip)).toEqual(expect.arrayContaining(['imsmanifest.xml', 'index.html', 'assets/app.js']));
    expect(strFromU8(zip['assets/app.js']!)).toBe(build['assets/app.js']);
    const manifest = strFromU8(zip['imsmanifest.xml']!);
    expect(manifest).toContain('2004 4th Edition');
    expect(manifest).toContain('Licht en schaduw');
  });
});

describe('rt-export-menu', () => {
  const progress = () => newProgress({ monotonicMs: () => 0, wallMs: () => Date.parse('2026-03-02T09:00:00Z') });

  it('offers nothing to hand in before there is progress', async () => {
    const menu = await mount('rt-export-menu', {});
    await expect.element(page.elementLocator(menu).getByRole('button', { name: 'Download results file' })).toBeDisabled();
    await expect.element(page.elementLocator(menu).getByRole('button', { name: 'Copy results code' })).toBeDisabled();
  });

  it('downloads one results file named with the participant code, holding the assignment and the code', async () => {
    const downloads = catchDownloads();
    const menu = await mount('rt-export-menu', { progress: progress(), participant: '5H2-03', assignment: CLASS_ASSIGNMENT, attemptId: 'attempt-1' });
    await page.elementLocator(menu).getByRole('button', { name: 'Download results file' }).click();
    await vi.waitFor(() => expect(downloads).toHaveLength(1));
    expect(downloads[0]!.name).toMatch(/5H2-03.*\.json$/);
    const file = JSON.parse(await downloads[0]!.blob.text());
    expect([file.participant, file.assignment.title, file.learner.attemptId]).toEqual(['5H2-03', CLASS_ASSIGNMENT.title, 'attempt-1']);
  });

  it('shows the results code to copy, which reads back as the same results', async () => {
    const menu = await mount('rt-export-menu', { progress: progress(), participant: '5H2-03', assignment: CLASS_ASSIGNMENT, attemptId: 'attempt-1' });
    const view = page.elementLocator(menu);
    await view.getByRole('button', { name: 'Copy results code' }).click();
    const box = view.getByRole('textbox', { name: 'Your results code' });
    await expect.element(box).toBeVisible();
    const code = (box.element() as HTMLTextAreaElement).value;
    expect(code.startsWith(RESULTS_CODE_PREFIX)).toBe(true);
    expect(JSON.parse(decodeResultsCode(code)!).participant).toBe('5H2-03');

    // Pressed again for another code (a shared computer): the box shows the new code, not the first.
    menu.participant = '5H2-04';
    await view.getByRole('button', { name: 'Copy results code' }).click();
    await vi.waitFor(() => expect(JSON.parse(decodeResultsCode((box.element() as HTMLTextAreaElement).value)!).participant).toBe('5H2-04'));
  });

  it('makes the CSV for research with one row per task attempt', async () => {
    const downloads = catchDownloads();
    const menu = await mount('rt-export-menu', { progress: progress(), participant: '5H2-03', assignment: CLASS_ASSIGNMENT });
    await page.elementLocator(menu).getByRole('button', { name: 'Download CSV' }).click();
    await vi.waitFor(() => expect(downloads).toHaveLength(1));
    expect(downloads[0]!.name).toMatch(/\.csv$/);
    // No task was played: the header and no rows.
    expect((await downloads[0]!.blob.text()).trim().split('\n')).toHaveLength(1);
  });
});
