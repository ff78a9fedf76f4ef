import { expect, test, type Page } from '@playwright/test';
import { mkdirSync, writeFileSync } from 'node:fs';
import type { ViewProbes } from '../src/view/view-probes.ts';
import { collectErrors } from './support/game-steps.ts';
import { sliderLatencyOf, type SliderFrame, type SliderInput } from './support/slider-latency.ts';

/**
 * The live view's ray budget (issue 38): in the free lab with its largest settings
 * (supersampling 4, a lens of 4 × 4 points, 4 shutter times: 1,024 rays from the camera per
 * pixel, the most a scene may ask), the 3D view draws tens of thousands of rays, and on
 * SwiftShader a frame of them took seconds. While the red ball's Shininess slider is dragged
 * (a step per frame) and then nudged with the arrow key (a step per 150 ms), the view draws
 * a budget of them and says so; once the edits stop it draws them all again.
 *
 * Each step is timed from the slider's `input` event to the first frame of the 3D view that
 * shows its value (the view's probes' `drawnScene`), and to the first that shows rays traced with it
 * (`drawnRaysScene`: a screen this size is traced in the worker, so its rays come a trace
 * later). The figures go to test-results/ray-budget-<project>.json for `npm run bench`; the
 * ≤ 100 ms target is the benchmark's, so this test asserts what must always hold: the note,
 * rays drawn while the slider moves, no frame held for seconds, and every ray back after.
 */

const LABEL = 'Shininess (n)';
const BALL = 'red-ball';

interface Recording {
  inputs: SliderInput[];
  /** Frames that showed a new value of the slider. */
  frames: SliderFrame[];
  /** Frames that showed rays traced with a new value. */
  rayFrames: SliderFrame[];
  /** The rays drawn, whenever that number changed. */
  rayCounts: SliderFrame[];
}

async function typeInto(page: Page, label: string, value: string): Promise<void> {
  const field = page.locator('rt-tracer-panel').getByRole('textbox', { name: `${label}, typed value` });
  await field.scrollIntoViewIfNeeded();
  await field.fill(value);
  await field.press('Enter');
}

const drawnRays = async (page: Page) => Number(await page.locator('rt-scene-view').getAttribute('data-ray-instances'));

async function startRecording(page: Page): Promise<void> {
  await page.locator('rt-scene-view').evaluate(
    (element, [label, ball]) => {
      type Drawn = { objects: { id: string; material: { shininess: number } }[] } | null;
      const view: { drawnScene: Drawn; drawnRaysScene: Drawn } = (element as unknown as { labView: { probes: ViewProbes } }).labView.probes;
      const record = { inputs: [] as SliderFrame[], frames: [] as SliderFrame[], rayFrames: [] as SliderFrame[], rayCounts: [] as SliderFrame[] };
      (window as unknown as { budgetRecord: typeof record }).budgetRecord = record;
      window.addEventListener(
        'input',
        (event) => {
          const input = event.composedPath()[0];
          if (input instanceof HTMLInputElement && input.type === 'range' && input.getAttribute('aria-label') === label)
            record.inputs.push({ at: event.timeStamp, value: Number(input.value) });
        },
        true,
      );
      const shininess = (scene: Drawn) => scene?.objects.find((object) => object.id === ball)?.material.shininess;
      let last: number | undefined;
      let lastRays: number | undefined;
      let lastCount = -1;
      // Checked once a frame: a frame is seen in it or at the next one.
      const frame = () => {
        const at = performance.now();
        const value = shininess(view.drawnScene);
        const rays = shininess(view.drawnRaysScene);
        if (value !== undefined && value !== last) record.frames.push({ at, value });
        if (rays !== undefined && rays !== lastRays) record.rayFrames.push({ at, value: rays });
        last = value;
        lastRays = rays;
        const count = Number(element.getAttribute('data-ray-instances'));
        if (count !== lastCount) record.rayCounts.push({ at, value: count });
        lastCount = count;
        requestAnimationFrame(frame);
      };
      requestAnimationFrame(frame);
    },
    [LABEL, BALL] as const,
  );
}

async function takeRecording(page: Page): Promise<Recording> {
  return page.evaluate(() => {
    const record = (window as unknown as { budgetRecord: Recording }).budgetRecord;
    const taken = { inputs: [...record.inputs], frames: [...record.frames], rayFrames: [...record.rayFrames], rayCounts: [...record.rayCounts] };
    for (const list of Object.values(record)) list.length = 0;
    return taken;
  });
}

test('with the free lab’s largest settings the view draws a budget of the rays while a slider moves, says so, and all of them after', async ({ page }) => {
  test.slow();
  const errors = collectErrors(page);
  await page.goto('./#free-lab');
  const view = page.locator('rt-scene-view');
  await expect(view).toHaveAttribute('data-ray-instances', /^[1-9]\d*$/, { timeout: 60_000 });
  await typeInto(page, 'Aperture (lens radius)', '0.2');
  for (const [label, value] of [
    ['Supersampling (s)', '4'],
    ['Lens samples (n)', '4'],
    ['Time samples (k)', '4'],
  ])
    await typeInto(page, label, value);
  const note = page.getByTestId('ray-thinning');
  // The rays of the last setting typed: a screen of the ones before has more than 20,000 too.
  await expect
    .poll(() => view.evaluate((element) => (element as unknown as { labView: { probes: ViewProbes } }).labView.probes.drawnRaysScene?.settings.timeSamples), {
      message: 'the rays of the last setting are drawn',
      timeout: 60_000,
    })
    .toBe(4);
  // Every ray of the heavy screen, once the edits have stopped.
  await expect.poll(() => drawnRays(page), { message: 'the whole screen is drawn once the settings are in', timeout: 60_000 }).toBeGreaterThan(20_000);
  await expect(note).toBeEmpty();
  const all = await drawnRays(page);
  await drawnAll(page);

  await page
    .locator('rt-scene-list')
    .getByRole('option', { name: /Red ball/ })
    .click();
  const slider = page.locator('rt-object-panel').getByRole('slider', { name: LABEL });
  await slider.scrollIntoViewIfNeeded();
  await startRecording(page);
  const figures: Record<string, unknown> = {};

  // A drag of 60 steps, a frame apart.
  const box = (await slider.boundingBox())!;
  const y = box.y + box.height / 2;
  await page.mouse.move(box.x + box.width * 0.1, y);
  await page.mouse.down();
  for (let step = 1; step <= 60; step++) {
    await page.mouse.move(box.x + box.width * (0.1 + (0.8 * step) / 60), y);
    await page.waitForTimeout(16);
    if (step === 30) {
      // Halfway: the note says how many rays are drawn, traced from one sample a pixel, and how many the screen had before; the canvas draws them.
      await expect(note).toHaveText(
        /^Showing [\d,]+ rays while you edit, each pixel traced from one of its samples \([\d,]+ rays before the edit\)\. All come back when you stop\.$/,
      );
      const [shown, before] = (await note.textContent())!.match(/[\d,]{2,}/g)!.map((count) => Number(count.replaceAll(',', '')));
      expect(before, 'the note counts the screen traced whole before the drag').toBeGreaterThanOrEqual(all);
      expect(shown, 'a budget of them is drawn').toBeLessThan(all / 10);
      expect(await coveredPixels(page), 'the canvas draws the rays it keeps').toBeGreaterThan(500);
    }
  }
  await page.mouse.up();
  const dragEnd = Number(await slider.inputValue());
  await expect.poll(async () => (await takeLast(page)).rays, { message: 'the last value’s rays are drawn', timeout: 30_000 }).toBe(dragEnd);
  const dragged = await takeRecording(page);
  // Stopped: every ray again, and no note; the keys start once that frame is drawn.
  figures.drag = { ...figuresOf(dragged), allRaysAfterMs: await drawnAll(page, all, dragged.inputs.at(-1)!.at) };
  await takeRecording(page);

  // Arrow keys: 30 presses, 150 ms apart, timed as a whole as the issue timed 8 of them.
  await slider.focus();
  const started = Date.now();
  for (let press = 0; press < 30; press++) {
    await page.keyboard.press('ArrowRight');
    await page.waitForTimeout(150);
  }
  const keysEnd = Number(await slider.inputValue());
  await expect.poll(async () => (await takeLast(page)).rays, { message: 'the last key’s rays are drawn', timeout: 30_000 }).toBe(keysEnd);
  const pressed = await takeRecording(page);
  figures.keys = { ...figuresOf(pressed), wallMs: Date.now() - started, allRaysAfterMs: await drawnAll(page, all, pressed.inputs.at(-1)!.at) };

  mkdirSync('test-results', { recursive: true });
  const file = `test-results/ray-budget-${test.info().project.name}.json`;
  writeFileSync(
    file,
    `${JSON.stringify({ measured: new Date().toISOString(), settings: { supersampling: 4, lensSamples: 4, timeSamples: 4, screen: [8, 6] }, allRays: all, ...figures }, null, 2)}\n`,
  );
  for (const [name, figure] of Object.entries(figures) as [string, ReturnType<typeof figuresOf>][]) {
    expect(figure.view.undrawn, `${name}: every step reached a frame`).toBe(0);
    expect(figure.rays.undrawn, `${name}: every step's rays (or a later step's) came`).toBe(0);
    expect(figure.rays.shownDuring, `${name}: new rays came while the slider moved`).toBeGreaterThanOrEqual(1);
    expect(figure.mostRays, `${name}: the budget held while the slider moved`).toBeLessThan(all / 10);
  }
  // Before the budget a frame of these rays took 4–11 s on SwiftShader: 8 steps took a minute.
  expect((figures.keys as { wallMs: number }).wallMs, 'thirty arrow-key steps took').toBeLessThan(60_000);

  expect(errors).toEqual([]);
});

/**
 * Waits until all `rays` are drawn with no note (the edits have stopped), every piece of
 * them is on the canvas, and that frame has reached the screen; returns the time from
 * `since` (page time) to then.
 */
async function drawnAll(page: Page, rays?: number, since?: number): Promise<number> {
  if (rays !== undefined) await expect.poll(() => drawnRays(page), { message: 'all rays are drawn once the slider stops', timeout: 60_000 }).toBe(rays);
  await expect(page.getByTestId('ray-thinning')).toBeEmpty();
  // On SwiftShader a screen this heavy is drawn a piece a frame (view/piecewise-rays.ts): the last piece too.
  await expect
    .poll(() => page.locator('rt-scene-view').evaluate((element) => (element as unknown as { labView: { probes: ViewProbes } }).labView.probes.raysComplete), {
      timeout: 120_000,
    })
    .toBe(true);
  return page.locator('rt-scene-view').evaluate((element, from) => {
    // Reading a pixel back waits for the software GPU to finish the frames it was given.
    const gl = (element as unknown as { labView: { renderer: { getContext(): WebGLRenderingContext } } }).labView.renderer.getContext();
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array(4));
    return Math.round(performance.now() - (from ?? 0));
  }, since);
}

/** The value the last frame showed, and the value its rays were traced with. */
async function takeLast(page: Page): Promise<{ view?: number; rays?: number }> {
  return page.evaluate(() => {
    const record = (window as unknown as { budgetRecord: Recording }).budgetRecord;
    return { view: record.frames.at(-1)?.value, rays: record.rayFrames.at(-1)?.value };
  });
}

/** A step's time to a frame of its value, and to a frame of rays traced with it; the most rays a frame drew until the last step. */
function figuresOf({ inputs, frames, rayFrames, rayCounts }: Recording) {
  const strip = ({ steps, p50Ms, p95Ms, maxMs, undrawn, shownDuring }: ReturnType<typeof sliderLatencyOf>) => ({
    steps,
    p50Ms,
    p95Ms,
    maxMs,
    undrawn,
    shownDuring,
  });
  const [firstStep, lastStep] = [inputs[0]?.at ?? 0, inputs.at(-1)?.at ?? 0];
  const mostRays = Math.max(0, ...rayCounts.filter(({ at }) => at > firstStep && at <= lastStep).map(({ value }) => value));
  return { view: strip(sliderLatencyOf({ inputs, frames })), rays: strip(sliderLatencyOf({ inputs, frames: rayFrames })), mostRays };
}

/** CSS pixels of the canvas that the drawn rays change (ViewProbes.rayCoverage). */
async function coveredPixels(page: Page): Promise<number> {
  return page.locator('rt-scene-view').evaluate((element) => {
    const { mask } = (element as unknown as { labView: { probes: ViewProbes } }).labView.probes.rayCoverage();
    return mask.reduce((sum, covered) => sum + covered, 0);
  });
}
