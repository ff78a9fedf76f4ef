// Every task's start view of the levels, as a learner sees it at 1366×768, in English and
// Dutch: `npx tsx scripts/task-screenshots.ts [level-id …]` with the built app served
// (`npm start`, or SCREENSHOT_URL; SCREENSHOT_LANGUAGES=nl for one language). Pictures go to
// build/screenshots/<language>/. Each task
// is solved the way a stuck learner would: Next, a prediction (the first choice, or the
// answer typed), Continue after its explanation, or the hint ladder's "Show me".
import { chromium, type Page } from '@playwright/test';
import { mkdirSync, readFileSync } from 'node:fs';

const url = process.env.SCREENSHOT_URL ?? 'http://127.0.0.1:4173/';
const index = JSON.parse(readFileSync('levels/index.json', 'utf8')) as { chapters: { levels: string[] }[] };
const order = index.chapters.flatMap((chapter) => chapter.levels);
const wanted = process.argv.slice(2).length > 0 ? process.argv.slice(2) : order;

interface LevelFile {
  tasks: { id: string; mandatory?: boolean; goal: { estimate?: { answer: number } } }[];
}
const readLevel = (id: string) => JSON.parse(readFileSync(`levels/${id}.level.json`, 'utf8')) as LevelFile;

/** Progress in which every level before `id` is passed, in `locale`. */
function progressBefore(id: string, locale: string): string {
  const levels = Object.fromEntries(
    order.slice(0, order.indexOf(id)).map((level) => [
      level,
      {
        tasks: Object.fromEntries(
          readLevel(level)
            .tasks.filter((task) => task.mandatory !== false)
            .map((task) => [task.id, { how: 'done', points: 0 }]),
        ),
        hintsUsed: 0,
      },
    ]),
  );
  return JSON.stringify({
    kind: 'ray-tracer-quest-progress',
    version: 1,
    levels,
    badges: [],
    settings: { locale },
    sandbox: null,
    current: null,
    log: { startedAt: new Date().toISOString(), events: [] },
  });
}

async function solveCurrent(page: Page, level: LevelFile): Promise<void> {
  const card = page.locator('rt-task-card[status="current"]');
  const id = await card.getAttribute('data-task');
  const quiz = card.locator('rt-quiz');
  if (await quiz.count()) {
    const estimate = level.tasks.find((task) => task.id === id)?.goal.estimate;
    if (estimate) await quiz.getByRole('textbox').fill(String(estimate.answer));
    else await quiz.getByRole('radio').first().check();
    await quiz.locator('button.primary').click();
    return;
  }
  const next = card.locator('.actions button.primary');
  if (await next.count()) return next.click();
  for (let step = 0; step < 6; step++) {
    const button = card.locator('rt-hint-box button[data-hint]');
    if (!(await button.count())) return;
    const kind = await button.getAttribute('data-hint');
    await button.click();
    if (kind === 'show-me') return;
  }
}

/** A revealed prediction: say what is seen (if asked), then Continue; `shot` saves each stage first. */
async function continueAfterReveal(page: Page, shot: (stage: string) => Promise<void>): Promise<void> {
  for (let step = 0; step < 2; step++) {
    const quiz = page.locator('rt-task-card[expanded]:not([status="current"]) rt-quiz');
    const button = quiz.locator('button.primary');
    if (!(await button.count())) return;
    await shot(step === 0 ? 'revealed' : 'explained');
    const radio = quiz.getByRole('radio');
    if ((await radio.count()) && !(await radio.first().isDisabled())) await radio.first().check();
    const box = quiz.getByRole('textbox');
    if ((await box.count()) && !(await box.isDisabled())) await box.fill('0');
    await button.click();
    await page.waitForTimeout(200);
  }
}

const browser = await chromium.launch({
  executablePath: process.env.CHROMIUM_PATH ?? '/usr/bin/chromium',
  args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader'],
});
for (const locale of (process.env.SCREENSHOT_LANGUAGES ?? 'en,nl').split(',')) {
  mkdirSync(`build/screenshots/${locale}`, { recursive: true });
  for (const id of wanted) {
    const level = readLevel(id);
    const page = await browser.newPage({ viewport: { width: 1366, height: 768 } });
    await page.addInitScript(
      (saved) => {
        if (sessionStorage.getItem('seeded')) return;
        sessionStorage.setItem('seeded', 'yes');
        localStorage.setItem('rtq.progress', saved);
      },
      progressBefore(id, locale),
    );
    await page.goto(`${url}?lang=${locale}`);
    const welcome = page
      .locator('rt-lab')
      .getByRole('button')
      .filter({ hasText: /Got it|Begrepen/ });
    if (await welcome.count()) await welcome.first().click();
    if (!(await page.locator('rt-level-map').isVisible())) await page.locator('[data-command="levels"]').click();
    await page.locator(`rt-level-map [data-level="${id}"]`).click();
    const seen = new Set<string>();
    // "Show me" plays a task's solution visibly, a render takes seconds: wait for the next task.
    for (let step = 0; step < 60; step++) {
      await page.waitForTimeout(1000);
      await continueAfterReveal(page, (stage) =>
        page.screenshot({ path: `build/screenshots/${locale}/${id}--${String(seen.size).padStart(2, '0')}-${stage}.png` }).then(() => undefined),
      );
      const current = page.locator('rt-task-card[status="current"]');
      if (await page.locator('rt-quest-panel section.celebration').count()) break;
      if (!(await current.count())) continue;
      // The task can finish between the count and the read (a render ending): look again next round.
      const task = await current.getAttribute('data-task', { timeout: 1000 }).catch(() => null);
      if (task === null || seen.has(task)) continue;
      seen.add(task);
      await page.waitForTimeout(1000);
      await page.screenshot({ path: `build/screenshots/${locale}/${id}--${String(seen.size).padStart(2, '0')}-${task}.png` });
      await solveCurrent(page, level);
    }
    console.log(`${locale} ${id}: ${seen.size} tasks`);
    await page.close();
  }
}
await browser.close();
