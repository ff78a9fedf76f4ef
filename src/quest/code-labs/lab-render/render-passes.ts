import { judge, type CaseFailure, type LabAnswer, type LabOutcome, type Tolerance } from '../code-lab-grading.ts';
import { labFunctions, referenceAnswer, type RenderLab } from './lab-functions.ts';
import type { LabCamera } from './lab-camera.ts';
import { renderLab } from './lab-renderer.ts';
import type { LabRenderScene } from './lab-render-scene.ts';

/** What a lab render came to: the two images, or why the learner's one could not be made. */
export type LabRenderResult =
  | { kind: 'rendered'; mine: Float32Array; reference: Float32Array; passes: number; calls: number }
  /** An answer the render cannot use (the function threw, gave NaN or a wrong kind of value): the call and the failure, as the grader words it. */
  | { kind: 'bad-answer'; failure: CaseFailure }
  /** Each pass still met calls never asked before, after `passes` passes. */
  | { kind: 'too-many-passes'; passes: number }
  /** The sandbox gave no answers (a syntax error, a time-out…): what it said. */
  | { kind: 'no-answers'; reason: unknown };

/** Asks the learner's function for all these calls at once (in the sandbox): their outcomes in order, or why there are none. */
export type AskLearner = (calls: unknown[][]) => Promise<{ outcomes: LabOutcome[] } | { reason: unknown }>;

/**
 * The most passes a render may take: one per depth of rays whose inputs follow from the
 * learner's earlier answers (the camera rays, then the rays of each bounce up to maxDepth,
 * then the shadow rays of the last bounce), plus the pass that finds every answer known.
 */
export const maxPasses = (maxDepth: number): number => maxDepth + 3;

/**
 * Renders with the learner's function in passes (the learner's code runs only in the
 * sandbox, never here): each pass renders the whole image, answering every call of the lab's
 * function from a table of the learner's answers keyed by the call's arguments; a call not in
 * the table is noted and answered by the tracer's own function for now. The noted calls go
 * to the learner's function in one batch, their answers fill the table, and the next pass
 * renders again, until a pass meets no new call: that pass's image is the learner's. The
 * camera is the level's unless another is given (the box lab's view along an axis, axis-view.ts).
 *
 * Each answer is judged as Run tests judges it (code-lab-grading.ts `judge`, the lab's
 * tolerance): one the grader accepts goes into the table as the tracer's own answer, so a
 * correct function renders the reference image exactly and every difference comes from an
 * answer the grader would fail; a wrong value is used as it is; a wrong kind of answer (an
 * exception, NaN, no vector) stops the render with that call.
 */
export async function renderWithLearner(
  scene: LabRenderScene,
  lab: RenderLab,
  tolerance: Tolerance,
  ask: AskLearner,
  width: number,
  height: number,
  camera?: LabCamera,
): Promise<LabRenderResult> {
  const reference = await renderLab(
    scene,
    labFunctions(null, () => null),
    width,
    height,
    { camera },
  );
  const answers = new Map<string, LabAnswer>();
  const limit = maxPasses(scene.source.settings.maxDepth);
  for (let pass = 1; pass <= limit; pass++) {
    const missed = new Map<string, unknown[]>();
    const lookUp = (args: unknown[]): LabAnswer => {
      const key = JSON.stringify(args);
      const known = answers.get(key);
      if (known !== undefined) return known;
      missed.set(key, args);
      return referenceAnswer(lab, args);
    };
    const mine = await renderLab(scene, labFunctions(lab, lookUp), width, height, { camera });
    if (missed.size === 0) return { kind: 'rendered', mine, reference, passes: pass, calls: answers.size };
    const calls = [...missed.values()];
    const reply = await ask(calls);
    if ('reason' in reply) return { kind: 'no-answers', reason: reply.reason };
    const keys = [...missed.keys()];
    for (const [index, args] of calls.entries()) {
      const expected = referenceAnswer(lab, args);
      const failure = judge({ kind: 'render', args, expected }, reply.outcomes[index] ?? { threw: 'no answer', line: null }, tolerance, index);
      if (failure && !USABLE.has(failure.reason)) return { kind: 'bad-answer', failure };
      answers.set(keys[index]!, failure ? failure.gotValue : expected);
    }
  }
  return { kind: 'too-many-passes', passes: limit };
}

/** Failures whose answer is of the kind asked for, so the render can use it: a wrong value, null or not, or a direction not of length 1. */
const USABLE = new Set<CaseFailure['reason']>(['wrong-value', 'expected-miss', 'expected-hit', 'not-unit']);
