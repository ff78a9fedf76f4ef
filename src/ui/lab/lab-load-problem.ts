import { msg } from '@lit/localize';
import { html, nothing, type TemplateResult } from 'lit';
import type { LoadProblem } from '../../app/lab-services.ts';
import { ON_DEMAND_PANELS, RENDER_WINDOW } from './lab-elements.ts';
import '../controls/rt-load-problem.ts';

/**
 * Over the 3D view, code the lab loads after its first screen that could not be loaded (the
 * render workers, the view's ray layers, the ray debugger when the level shows it, the render
 * window): what is
 * missing and a Reload button each (rt-load-problem). The rest of the lab goes on: its
 * panels, its tasks, the progress.
 */
export function labLoadProblems(problems: readonly LoadProblem[], debuggerShown: boolean): TemplateResult | typeof nothing {
  const debuggerCode = ON_DEMAND_PANELS.debugger;
  const debuggerFailed = debuggerShown && debuggerCode?.state === 'failed';
  const renderWindowFailed = RENDER_WINDOW.state === 'failed';
  if (problems.length === 0 && !debuggerFailed && !renderWindowFailed) return nothing;
  const text = (problem: LoadProblem) =>
    problem.what === 'tracer'
      ? msg('The ray tracer could not be loaded: no rays are traced and no image can be rendered.')
      : msg("The 3D view's rays could not be loaded: the scene shows without them.");
  return html`<div class="lab-load-problems">
    ${problems.map((problem) => html`<rt-load-problem .text=${text(problem)} .reason=${problem.reason}></rt-load-problem>`)}
    ${debuggerFailed ? html`<rt-load-problem .text=${msg('The ray debugger could not be loaded.')} .reason=${debuggerCode.problem}></rt-load-problem>` : nothing}
    ${
      renderWindowFailed
        ? html`<rt-load-problem .text=${msg('The render window could not be loaded: no image can be rendered.')} .reason=${RENDER_WINDOW.problem}></rt-load-problem>`
        : nothing
    }
  </div>`;
}

/** `problems` with `problem` added, unless one of its kind is there already (each is said once). */
export function withProblem(problems: readonly LoadProblem[], problem: LoadProblem): readonly LoadProblem[] {
  return problems.some((each) => each.what === problem.what) ? problems : [...problems, problem];
}
