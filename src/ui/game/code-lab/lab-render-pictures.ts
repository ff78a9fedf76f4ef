import { msg, str } from '@lit/localize';
import { html, nothing, type TemplateResult } from 'lit';
import { ref } from 'lit/directives/ref.js';
import type { CodeGoal } from '../../../quest/code-labs/code-goal.ts';
import type { Tolerance } from '../../../quest/code-labs/code-lab-grading.ts';
import { topDownCamera } from '../../../quest/code-labs/lab-render/axis-view.ts';
import type { RenderLab } from '../../../quest/code-labs/lab-render/lab-functions.ts';
import { labRenderScene } from '../../../quest/code-labs/lab-render/lab-render-scene.ts';
import { DIFFERENCE_GAIN, pictureDifference } from '../../../quest/code-labs/lab-render/picture-difference.ts';
import { renderWithLearner, type AskLearner, type LabRenderResult } from '../../../quest/code-labs/lab-render/render-passes.ts';
import type { Scene } from '../../../scene/scene.ts';
import { toRgba8 } from '../../../tracer/quantize.ts';
import { axisViewLabels, axisViewTitle, axisViewWhy, levelViewLabels, viewsAlongAxis, type ViewLabels } from './axis-view-texts.ts';
import { caseInput, failureText, sandboxUnavailableText } from './code-lab-texts.ts';
import { failedRun, type LabSandbox, type SandboxResult } from './lab-sandbox.ts';

/**
 * How long one batch of a render's calls may take in the sandbox: tens of thousands of calls
 * (one per camera ray and sphere, and as many for shadow rays) where Run tests has a few
 * hundred; copying them to the sandbox and back takes most of it (about 2.4 s for 30 000
 * calls in headless Chromium on a shared 2-core machine).
 */
export const RENDER_LIMIT_MS = 10_000;

/** The size of a lab render: small enough that every pass is quick, large enough to see the scene. */
export const LAB_RENDER_WIDTH = 160;
export const LAB_RENDER_HEIGHT = 120;

/** What the pictures area shows: nothing yet, a render under way, the three pictures, or why there are none. */
export type LabRenderState =
  | { kind: 'idle' }
  | { kind: 'rendering' }
  /**
   * `caption`: what the pictures show, under them (`agree`: nothing there points to a mistake); no difference picture where
   * the renders are noisy. `alongAxis`: the box lab's second view, from straight above (axis-view.ts).
   */
  | { kind: 'rendered'; mine: ImageData; reference: ImageData; difference: ImageData | null; caption: string; agree: boolean; alongAxis?: LabRenderState }
  | { kind: 'stopped'; message: string };

/**
 * Renders the level's scene with the learner's function (render-passes.ts): each batch of
 * calls runs in the sandbox, like Run tests, with the same time limit. The box lab renders it
 * a second time from straight above (axis-view.ts), where every ray is parallel to two of a
 * box's three slabs.
 */
export async function renderLabPictures(
  goal: CodeGoal,
  lab: RenderLab,
  tolerance: Tolerance,
  scene: Scene,
  code: string,
  sandbox: LabSandbox,
): Promise<LabRenderState> {
  const labScene = labRenderScene(scene);
  const ask = askSandbox(goal, code, sandbox);
  const level = pictures(await renderWithLearner(labScene, lab, tolerance, ask, LAB_RENDER_WIDTH, LAB_RENDER_HEIGHT), goal, tolerance, scene);
  if (level.kind !== 'rendered' || !viewsAlongAxis(lab)) return level;
  const fromAbove = await renderWithLearner(labScene, lab, tolerance, ask, LAB_RENDER_WIDTH, LAB_RENDER_HEIGHT, topDownCamera(labScene));
  return { ...level, alongAxis: pictures(fromAbove, goal, tolerance, scene) };
}

/** Each batch of a render's calls run in the sandbox, like Run tests, with a render's time limit. */
export const askSandbox =
  (goal: CodeGoal, code: string, sandbox: LabSandbox): AskLearner =>
  async (calls) => {
    const ran = await sandbox.run(code, goal.code.function, calls, { eachCase: false, limitMs: RENDER_LIMIT_MS }).catch((error: unknown) => {
      sandbox.close();
      return failedRun(error);
    });
    return ran.kind === 'ran' ? { outcomes: ran.outcomes } : { reason: ran };
  };

/** Three RGBA pictures of one size as the pictures area shows them. */
export function renderedPictures(mine: Uint8ClampedArray, reference: Uint8ClampedArray, difference: Uint8ClampedArray | null, width: number, height: number) {
  const image = (data: Uint8ClampedArray) => new ImageData(new Uint8ClampedArray(data), width, height);
  return { mine: image(mine), reference: image(reference), difference: difference && image(difference) };
}

function pictures(result: LabRenderResult, goal: CodeGoal, tolerance: Tolerance, scene: Scene): LabRenderState {
  switch (result.kind) {
    case 'rendered': {
      const bytes = (rgb: Float32Array) => toRgba8(rgb, LAB_RENDER_WIDTH, LAB_RENDER_HEIGHT, scene.settings);
      const mine = bytes(result.mine);
      const reference = bytes(result.reference);
      const { rgba, differing } = pictureDifference(mine, reference);
      const total = LAB_RENDER_WIDTH * LAB_RENDER_HEIGHT;
      const caption =
        differing === 0 ? msg(str`No pixel differs: your function renders the scene as the tracer’s does.`) : msg(str`${differing} of ${total} pixels differ.`);
      return { kind: 'rendered', ...renderedPictures(mine, reference, rgba, LAB_RENDER_WIDTH, LAB_RENDER_HEIGHT), caption, agree: differing === 0 };
    }
    case 'bad-answer': {
      const { failure } = result;
      const call = caseInput(goal.code.signature, failure.labCase.args);
      return {
        kind: 'stopped',
        message: msg(str`The render stopped at a call your function cannot answer: ${call}. ${failureText(failure, goal.code.lab, tolerance)}`),
      };
    }
    case 'too-many-passes':
      return tooManyPasses(result.passes);
    case 'no-answers':
      return noAnswers(result.reason);
  }
}

/** Why a render has no answers from the sandbox, worded as Run tests words it. */
export function noAnswers(reason: unknown): LabRenderState {
  const state = reason as Exclude<SandboxResult, { kind: 'ran' }>;
  const seconds = RENDER_LIMIT_MS / 1000;
  if (state.kind === 'timeout')
    return { kind: 'stopped', message: msg(str`Your function did not return within ${seconds} s while rendering. Is there a loop that never ends?`) };
  if (state.kind === 'no-function') return { kind: 'stopped', message: msg(str`There is no function named ${state.name} in your code.`) };
  if (state.kind === 'unavailable') return { kind: 'stopped', message: sandboxUnavailableText() };
  const message = state.line
    ? msg(str`Your code could not run: ${state.message} at line ${state.line}.`)
    : msg(str`Your code could not run: ${state.message}.`);
  return { kind: 'stopped', message };
}

/** The message of a render that stopped because each pass met calls not asked before. */
export const tooManyPasses = (passes: number): LabRenderState => ({
  kind: 'stopped',
  message: msg(str`The render stopped after ${passes} passes: each pass still met calls of your function not asked before.`),
});

/** Paints an image on its canvas once the canvas is on the page. */
const paint = (image: ImageData) =>
  ref((canvas) => {
    if (canvas instanceof HTMLCanvasElement) canvas.getContext('2d')?.putImageData(image, 0, 0);
  });

/**
 * The pictures side by side, each with a caption and a text alternative, and the line saying
 * what they show; then, in the box lab, the same for the view from above.
 */
export function labRenderPictures(state: LabRenderState, labels: ViewLabels = levelViewLabels()): TemplateResult | typeof nothing {
  switch (state.kind) {
    case 'idle':
      return nothing;
    case 'rendering':
      return html`<p>${msg('Rendering the scene with your function…')}</p>`;
    case 'stopped':
      return html`<p class="fail">${state.message}</p>`;
    case 'rendered': {
      const { caption, difference } = state;
      const figure = (image: ImageData, title: string, label: string) => html`
        <figure>
          <canvas width=${image.width} height=${image.height} role="img" aria-label=${label} ${paint(image)}></canvas>
          <figcaption>${title}</figcaption>
        </figure>
      `;
      return html`
        <div class="pictures">
          ${figure(state.mine, msg('Your function'), labels.mine)}
          ${figure(state.reference, msg('The tracer’s function'), labels.reference)}
          ${difference ? figure(difference, msg(str`Difference ×${DIFFERENCE_GAIN}`), msg(str`${labels.difference}, ${DIFFERENCE_GAIN} times brighter: ${caption}`)) : nothing}
        </div>
        <p class=${state.agree ? '' : 'fail'}>${caption}</p>
        ${
          state.alongAxis
            ? html`<section class="along-axis" aria-label=${axisViewTitle()}>
              <h4>${axisViewTitle()}</h4>
              <p>${axisViewWhy()}</p>
              ${labRenderPictures(state.alongAxis, axisViewLabels())}
            </section>`
            : nothing
        }
      `;
    }
  }
}
