import { expect, test } from '@playwright/test';

// The built app runs under a strict Content-Security-Policy (vite.config.ts): no inline
// script, no eval. The lab, a render in the workers and the export downloads cause no violation.

test('the built page has a strict CSP and a render breaks none of it', async ({ page }) => {
  await page.addInitScript(() => {
    const seen: string[] = [];
    (window as unknown as { cspViolations: string[] }).cspViolations = seen;
    document.addEventListener('securitypolicyviolation', (event) =>
      seen.push(`${event.violatedDirective} ${event.blockedURI} ${event.sourceFile}:${event.lineNumber}:${event.columnNumber} ${event.sample}`),
    );
  });
  await page.goto('./#free-lab');
  const policy = await page.locator('meta[http-equiv="Content-Security-Policy"]').getAttribute('content');
  expect(policy).toContain("script-src 'self'");
  expect(policy).not.toMatch(/unsafe-eval/);
  expect(policy).not.toMatch(/script-src[^;]*unsafe-inline/);

  await page.getByRole('button', { name: 'Render image' }).click();
  const renderWindow = page.locator('rt-render-window');
  await renderWindow.getByRole('button', { name: 'Render', exact: true }).click();
  await expect(renderWindow.getByTestId('render-status')).toContainText(/Done in [\d.]+ (ms|s)/, { timeout: 60_000 });
  const download = page.waitForEvent('download');
  await page.locator('rt-export-menu').getByRole('button', { name: 'Download results file' }).click();
  await download;
  expect(await page.evaluate(() => (window as unknown as { cspViolations: string[] }).cspViolations)).toEqual([]);
});
