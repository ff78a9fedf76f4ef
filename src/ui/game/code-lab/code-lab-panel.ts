import { msg } from '@lit/localize';
import { html, type TemplateResult } from 'lit';
import type { CodeGoal } from '../../../quest/code-labs/code-goal.ts';
import type { Locale } from '../../../quest/localized-text.ts';
import { LazyModule } from '../../../util/lazy-module.ts';

/**
 * The code lab panel's code (the editor, the grader and the tracer's function it compares
 * with) is loaded when a level first shows a code task, not with the first screen; the
 * element upgrades when it is there. One that cannot be loaded says so.
 */
const CODE_LAB = new LazyModule(() => import('./rt-code-lab.ts'));

export function codeLabPanel(goal: CodeGoal, locale: Locale, host: { requestUpdate(): void }): TemplateResult {
  if (CODE_LAB.state === 'idle') CODE_LAB.load().then(undefined, () => host.requestUpdate());
  if (CODE_LAB.state === 'failed') return html`<p role="alert">${msg('The code lab could not be loaded. Reload the page to try again.')}</p>`;
  return html`<rt-code-lab .goal=${goal} locale=${locale}></rt-code-lab>`;
}
