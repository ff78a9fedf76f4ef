import { hashKey } from '../../../tracer/sampler.ts';
import { samplePosition } from '../../../tracer/supersampling.ts';
import { pointsOf, type Point, type SampleFailure } from '../code-lab-statistics.ts';
import { labFunctions } from './lab-functions.ts';
import { renderLab } from './lab-renderer.ts';
import type { LabRenderScene } from './lab-render-scene.ts';
import type { AskLearner } from './render-passes.ts';

/**
 * Points per pixel in the samples lab's render: 4 × 4, enough that a stratified set draws a
 * smooth edge (16 levels of coverage) and a clumped or unstratified one a visibly rough one.
 */
export const SAMPLES_PER_PIXEL = 16;

/**
 * Point sets asked of the learner's function, one call each; every pixel takes one of them,
 * picked by its hash. A call per pixel (19 200 of them, 307 200 points) took 10 to 13 s to
 * copy out of the sandbox and back in Chromium on a shared 2-core machine; 1024 sets take
 * well under a second, and each pixel's points are still a set the function gave.
 */
export const POINT_SETS = 1024;

/** What the samples lab's render came to: the two images, or why the learner's one could not be made. */
export type SamplesRenderResult =
  | { kind: 'rendered'; mine: Float32Array; reference: Float32Array }
  /** An answer the render cannot use (the function threw, or gave no SAMPLES_PER_PIXEL points): which call (0-based) and why, as the grader words it. */
  | { kind: 'bad-answer'; call: number; failure: SampleFailure }
  /** The sandbox gave no answers (a syntax error, a time-out…): what it said. */
  | { kind: 'no-answers'; reason: unknown };

/**
 * Renders the level's scene with the learner's `pixelSamples` (the samples lab):
 * POINT_SETS calls pixelSamples(16, random), each with a random seeded as Run tests seeds
 * one (the learner's code runs only in the sandbox, all calls in one batch); each pixel takes
 * one of the sets and sends a ray through each of its 16 points, averaged (lab-renderer.ts,
 * every other function the tracer's). Beside it the same scene with the tracer's own
 * jittered 4 × 4 pattern for each pixel (supersampling.ts). A correct function need not give
 * the tracer's points for the same random (it may fill its cells in another order), so the
 * two pictures differ in noise even then: the render is for looking at the edges, not for
 * counting pixels.
 */
export async function renderSamplesWithLearner(
  scene: LabRenderScene,
  ask: AskLearner,
  width: number,
  height: number,
  seed: number,
): Promise<SamplesRenderResult> {
  const cells = Math.round(Math.sqrt(SAMPLES_PER_PIXEL));
  const out: [number, number] = [0, 0];
  const tracerPoints = (x: number, y: number): Point[] =>
    Array.from({ length: SAMPLES_PER_PIXEL }, (_, index) => {
      const [px, py] = samplePosition('jittered', cells, index, x, y, seed, out);
      return { x: px, y: py };
    });
  const functions = labFunctions(null, () => null);
  const reference = await renderLab(scene, functions, width, height, { pixelPoints: tracerPoints });
  const calls = Array.from({ length: POINT_SETS }, (_, set) => [SAMPLES_PER_PIXEL, { seededRandom: hashKey(seed, set) }]);
  const reply = await ask(calls);
  if ('reason' in reply) return { kind: 'no-answers', reason: reply.reason };
  const sets: Point[][] = [];
  for (let call = 0; call < calls.length; call++) {
    const outcome = reply.outcomes[call] ?? { threw: 'no answer', line: null };
    if ('threw' in outcome) return { kind: 'bad-answer', call, failure: { check: 'threw', run: call, message: outcome.threw, line: outcome.line } };
    const points = pointsOf(outcome.returned, SAMPLES_PER_PIXEL, call);
    if (!Array.isArray(points)) return { kind: 'bad-answer', call, failure: points };
    sets.push(points);
  }
  const mine = await renderLab(scene, functions, width, height, { pixelPoints: (x, y) => sets[hashKey(seed, x, y) % POINT_SETS]! });
  return { kind: 'rendered', mine, reference };
}
