import { expect, test } from '@playwright/test';
import { simulatedClassFiles } from '../tests/support/class-exports.ts';
import { expectAccessible } from './support/axe.ts';

// axe-core on every page of the app, in both languages and both themes: the lab in level 1,
// the level map, the render window, the free lab with every panel (each section open) and
// the ray debugger's dock open, the teacher page, the dashboard (with a class read) and
// the survey. No serious or critical violation anywhere (WCAG 2.1 AA as axe checks it:
// names, roles, contrast, labels). The map and the render window are checked on their own
// (the lab under them was checked just before).

const classFiles = simulatedClassFiles(3);
const DEBUG_A_PIXEL = { en: 'Debug a pixel', nl: 'Pixel stap voor stap' } as const;

for (const lang of ['en', 'nl'] as const) {
  test(`no serious axe violation in the lab, the level map and the render window (${lang})`, async ({ page }) => {
    // axe's contrast rule walks every element in two themes: minutes on a busy school machine.
    test.slow();
    const at = (hash: string) => page.goto(`./?lang=${lang}${hash}`);

    await at('');
    await expect(page.locator('html')).toHaveAttribute('lang', lang);
    await expect(page.locator('rt-lab .welcome button')).toBeVisible();
    await expectAccessible(page, 'the lab in level 1');
    await page.locator('rt-lab .welcome button').click();

    await page.locator('[data-command="levels"]').click();
    await expect(page.locator('rt-level-map [data-level="01-introduction"]')).toBeVisible();
    await expectAccessible(page, 'the level map', { fromShadowDom: ['rt-app rt-lab', 'rt-level-map'] });
    await page.locator('rt-level-map [data-level="01-introduction"]').click();

    await page.locator('[data-command="render-open"]').click();
    await expect(page.locator('rt-render-window')).toBeVisible();
    await expectAccessible(page, 'the render window', { fromShadowDom: ['rt-app rt-lab', 'rt-render-window'] });

    // The free lab: every panel, each of its sections open, and the ray debugger's dock open on a pixel.
    // Only the hash changes: the game follows it to the free lab without a new page.
    await at('#free-lab');
    await expect(page.locator('rt-lab')).toHaveAttribute('free-lab', '');
    const pixel = page.locator('rt-screen-preview').getByRole('button', { name: 'Pixel 2, 1', exact: true });
    await pixel.click();
    await page.getByRole('button', { name: DEBUG_A_PIXEL[lang] }).click();
    await expect(page.locator('rt-ray-debugger')).toHaveAttribute('open', '');
    await page.locator('rt-panel-section').evaluateAll((sections) => sections.forEach((section) => ((section as HTMLElement & { open: boolean }).open = true)));
    await page.screenshot({ path: `test-results/screens/axe-free-lab-debugger-${lang}.png` });
    await expectAccessible(page, 'the free lab with every panel and the ray debugger');
  });

  test(`no serious axe violation on the classroom pages (${lang})`, async ({ page }) => {
    test.slow();
    const at = (hash: string) => page.goto(`./?lang=${lang}${hash}`);
    await at('#/teacher');
    await expect(page.locator('rt-teacher-page')).toBeVisible();
    await expectAccessible(page, 'the teacher page');

    await at('#/dashboard');
    const dashboard = page.locator('rt-dashboard-page');
    await dashboard
      .locator('input[type=file]')
      .setInputFiles(classFiles.map((file) => ({ name: file.name, mimeType: 'application/json', buffer: Buffer.from(file.text) })));
    await expect(dashboard.locator('section.level').first()).toBeVisible();
    await expectAccessible(page, 'the dashboard');

    await at('#/survey/default');
    await expect(page.locator('rt-survey')).toBeVisible();
    await expectAccessible(page, 'the survey');
  });
}
