import AxeBuilder from '@axe-core/playwright';
import { expect, type Page } from '@playwright/test';
import type { SerialFrameSelector } from 'axe-core';

// axe-core (Deque's accessibility rules engine) on the page as it is now. A page must have no
// serious or critical violation; moderate and minor ones (landmark advice) are reported by the
// rules but do not fail the suite.

/** The violations of impact serious or critical, one readable line per node. */
export async function seriousViolations(page: Page, scope?: SerialFrameSelector): Promise<string[]> {
  const builder = new AxeBuilder({ page });
  if (scope) builder.include(scope);
  const results = await builder.analyze();
  return results.violations
    .filter((violation) => violation.impact === 'serious' || violation.impact === 'critical')
    .flatMap((violation) =>
      violation.nodes.map(
        (node) => `${violation.id} (${violation.impact}): ${JSON.stringify(node.target)} — ${node.failureSummary?.replace(/\s+/g, ' ') ?? violation.help}`,
      ),
    );
}

/**
 * Fails with the serious and critical violations on `page` (or inside `scope`), in the light
 * and the dark theme: the system's colour scheme, which the app follows unless the learner
 * picked a theme. `where` names the page in the failure.
 */
export async function expectAccessible(page: Page, where: string, scope?: SerialFrameSelector): Promise<void> {
  for (const colorScheme of ['light', 'dark'] as const) {
    await page.emulateMedia({ colorScheme });
    expect(await seriousViolations(page, scope), `axe-core on ${where} (${colorScheme} theme)`).toEqual([]);
  }
}
