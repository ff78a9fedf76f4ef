import { msg, str } from '@lit/localize';
import type { CodeGoal } from '../../../quest/code-labs/code-goal.ts';
import type { SampleFailure } from '../../../quest/code-labs/code-lab-statistics.ts';
import { meanBrightness, renderCosineWithLearner, type CosineRenderResult } from '../../../quest/code-labs/lab-render/cosine-render.ts';
import { labRenderScene } from '../../../quest/code-labs/lab-render/lab-render-scene.ts';
import { pictureDifference } from '../../../quest/code-labs/lab-render/picture-difference.ts';
import { renderSamplesWithLearner, SAMPLES_PER_PIXEL } from '../../../quest/code-labs/lab-render/samples-render.ts';
import type { Scene } from '../../../scene/scene.ts';
import { fieldNumber } from '../../../i18n/number-format.ts';
import { toRgba8 } from '../../../tracer/quantize.ts';
import { askSandbox, LAB_RENDER_HEIGHT, LAB_RENDER_WIDTH, noAnswers, renderedPictures, tooManyPasses, type LabRenderState } from './lab-render-pictures.ts';
import { labNumber, labValue } from './lab-numbers.ts';
import type { LabSandbox } from './lab-sandbox.ts';

/** The labs of a random function that render with it: their pictures differ in noise even when the function is right. */
export const RANDOM_RENDER_LABS = ['pixel-samples', 'cosine-bounce'] as const;
export type RandomRenderLab = (typeof RANDOM_RENDER_LABS)[number];
export const rendersRandomly = (lab: string): lab is RandomRenderLab => (RANDOM_RENDER_LABS as readonly string[]).includes(lab);

/** The cosine lab's render size: a path render is far slower per pixel than the other labs' one ray. */
export const COSINE_RENDER_SIZE = 64;

/**
 * How far the two mean brightnesses may lie apart before the caption says it is more than
 * noise: a correct function's came within about 3 % of the tracer's (docs/code-labs.md).
 */
const NOISE_RATIO = 0.05;

/** Renders the level's scene with the learner's random function beside the tracer's (samples-render.ts, cosine-render.ts). */
export async function renderRandomLabPictures(goal: CodeGoal, lab: RandomRenderLab, scene: Scene, code: string, sandbox: LabSandbox): Promise<LabRenderState> {
  const ask = askSandbox(goal, code, sandbox);
  const seed = goal.code.cases.seed;
  if (lab === 'pixel-samples') {
    const result = await renderSamplesWithLearner(labRenderScene(scene), ask, LAB_RENDER_WIDTH, LAB_RENDER_HEIGHT, seed);
    if (result.kind === 'no-answers') return noAnswers(result.reason);
    if (result.kind === 'bad-answer') return { kind: 'stopped', message: pointSetFailureText(result.call + 1, result.failure) };
    const bytes = (rgb: Float32Array) => toRgba8(rgb, LAB_RENDER_WIDTH, LAB_RENDER_HEIGHT, scene.settings);
    const mine = bytes(result.mine);
    const reference = bytes(result.reference);
    const caption = msg(
      'Compare the edges: with one random point in each of the 4 × 4 cells they are as smooth as the tracer’s (only the noise differs); points clumped together make them jagged, random points that are not one per cell make them noisier, and points outside the pixel blur or shift them.',
    );
    return {
      kind: 'rendered',
      ...renderedPictures(mine, reference, pictureDifference(mine, reference).rgba, LAB_RENDER_WIDTH, LAB_RENDER_HEIGHT),
      caption,
      agree: true,
    };
  }
  const size = COSINE_RENDER_SIZE;
  return cosinePictures(await renderCosineWithLearner(scene, ask, size, size, seed), scene, size);
}

function cosinePictures(result: CosineRenderResult, scene: Scene, size: number): LabRenderState {
  switch (result.kind) {
    case 'no-answers':
      return noAnswers(result.reason);
    case 'too-many-passes':
      return tooManyPasses(result.passes);
    case 'bad-answer':
      return { kind: 'stopped', message: directionFailureText(result) };
    case 'rendered': {
      // Shown as path mode shows its pictures: radiance times 2^exposure, sRGB-encoded (quantize.ts).
      const settings = { ...scene.settings, integrator: 'path' as const };
      const mine = meanBrightness(result.mine, settings.exposure);
      const reference = meanBrightness(result.reference, settings.exposure);
      const ratio = mine / reference - 1;
      // One decimal, so that a difference just inside the noise band and one just outside it do not print alike.
      const percent = fieldNumber(Math.abs(ratio) * 100, 1);
      const [mineText, referenceText] = [fieldNumber(mine, 3), fieldNumber(reference, 3)];
      const brightness = msg(str`Mean brightness: your picture ${mineText}, the tracer’s ${referenceText}.`);
      const close = Math.abs(ratio) <= NOISE_RATIO;
      const verdict = close
        ? msg(str`They lie ${percent} % apart: as close as two noisy renders of the same density come.`)
        : ratio < 0
          ? msg(
              str`Yours is ${percent} % darker, more than the noise explains. This render weighs each of your directions by the albedo alone, which is right only for the density cos θ / π: do your directions have that density?`,
            )
          : msg(
              str`Yours is ${percent} % brighter, more than the noise explains. This render weighs each of your directions by the albedo alone, which is right only for the density cos θ / π: do your directions have that density?`,
            );
      const bytes = (rgb: Float32Array) => toRgba8(rgb, size, size, settings);
      return {
        kind: 'rendered',
        ...renderedPictures(bytes(result.mine), bytes(result.reference), null, size, size),
        caption: `${brightness} ${verdict}`,
        agree: close,
      };
    }
  }
}

function pointSetFailureText(call: number, failure: SampleFailure): string {
  const n = SAMPLES_PER_PIXEL;
  switch (failure.check) {
    case 'threw':
      return failure.line
        ? msg(str`The render stopped at call ${call}, pixelSamples(${n}, random): your function threw ${failure.message} at line ${failure.line}.`)
        : msg(str`The render stopped at call ${call}, pixelSamples(${n}, random): your function threw ${failure.message}.`);
    case 'wrong-count':
      return msg(str`The render stopped at call ${call}, pixelSamples(${n}, random): got ${failure.got} points instead of ${n}.`);
    default:
      return msg(str`The render stopped at call ${call}, pixelSamples(${n}, random): your function did not return an array of ${n} points {x, y}.`);
  }
}

function directionFailureText(result: Extract<CosineRenderResult, { kind: 'bad-answer' }>): string {
  const normal = labValue(result.normal);
  const problem = result.problem;
  if (problem.kind === 'not-unit') {
    const direction = labValue(problem.direction);
    // 12 digits: the check allows 1e-9, and a length off by less than 5e-7 would print as 1 to 6 digits.
    const length = labNumber(problem.length, 12);
    return msg(str`The render stopped: for the normal ${normal} your function returned ${direction}, of length ${length}. A direction must have length 1.`);
  }
  return problem.threw === null
    ? msg(str`The render stopped: for the normal ${normal} your function returned no vector of three finite numbers.`)
    : msg(str`The render stopped: for the normal ${normal} your function threw ${problem.threw}.`);
}
