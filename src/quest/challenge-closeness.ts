import { initialState } from '../lab-state/lab-state.ts';
import { reduce } from '../lab-state/lab-reducer.ts';
import type { RenderSettings, Scene } from '../scene/scene.ts';
import type { ChallengeGoal } from './goal.ts';

/**
 * The measure of a match-the-target challenge (spec/challenges.md §2). Both pictures are
 * rendered by the same tracer at the challenge's small size (64 × 48 unless the level says
 * otherwise) with the same seed, so the same scene gives the same picture, difference 0.
 *
 * The measure is the mean absolute difference per pixel and colour channel in linear light,
 * each value clamped to 0..1 as the picture shows it: 0 is the same picture, 1 is black
 * against white everywhere. For the learner: "on average, how far each pixel's red, green
 * and blue are from the target's". It is the plainest error there is (the L1 error in
 * linear light, before any display curve); a soft shadow's width or a lens's blur changes
 * many pixels a little, which it counts. In path mode the picture is radiance, shown times
 * 2^exposure (quantize.ts): it is measured as shown (shownLight), so that the number and
 * the difference picture mean for a dim room what they mean for any other picture.
 */

/** The target's scene and the learner's, both at the challenge's size, ready to render. */
export function challengeScenes(levelScene: Scene, goal: ChallengeGoal, learnerScene: Scene): { target: Scene; attempt: Scene } {
  let state = initialState(levelScene);
  // Refused actions change nothing; tests/quest/challenges.test.ts checks none is refused.
  for (const action of goal.challenge.target) state = reduce(state, action).state;
  return { target: atSize(state.scene, goal), attempt: atSize(learnerScene, goal) };
}

function atSize(scene: Scene, goal: ChallengeGoal): Scene {
  const imageSize: [number, number] = [goal.challenge.measure.size[0], goal.challenge.measure.size[1]];
  return { ...scene, settings: { ...scene.settings, imageSize } };
}

/** A render's linear RGB as the render window shows it: path mode's radiance times 2^exposure, Whitted mode's as it is. */
export function shownLight(rgb: Float32Array, settings: Pick<RenderSettings, 'integrator' | 'exposure'>): Float32Array {
  if (settings.integrator !== 'path') return rgb;
  const scale = 2 ** settings.exposure;
  return rgb.map((value) => value * scale);
}

/** The mean absolute difference of two linear RGB pictures of the same size, per pixel and channel, each value clamped to 0..1. */
export function meanLinearDifference(a: Float32Array, b: Float32Array): number {
  if (a.length !== b.length || a.length === 0) throw new Error(`pictures of different sizes: ${a.length} and ${b.length} values`);
  let sum = 0;
  for (let i = 0; i < a.length; i++) sum += Math.abs(clamp01(a[i]) - clamp01(b[i]));
  return sum / a.length;
}

/** Per pixel, the mean absolute difference of its three channels (0..1): what the difference picture shows. */
export function pixelDifferences(a: Float32Array, b: Float32Array): Float32Array {
  const out = new Float32Array(Math.floor(a.length / 3));
  for (let pixel = 0; pixel < out.length; pixel++) {
    let sum = 0;
    for (let c = 0; c < 3; c++) sum += Math.abs(clamp01(a[pixel * 3 + c]) - clamp01(b[pixel * 3 + c]));
    out[pixel] = sum / 3;
  }
  return out;
}

function clamp01(value: number): number {
  return Math.min(1, Math.max(0, value));
}

/** The match score of the threshold itself: a score at or above it is a match. */
export const MATCH_SCORE = 75;

/**
 * The difference as a pupil reads it (docs/levels.md): a match score from 0 to 100,
 * 75 − 25 · log₁₀(difference / threshold), rounded down. A raw difference of 0.0001 says
 * little; this says how close a render is to a match, the same way in every challenge:
 * 75 or more is a match, every ten times closer to the target adds 25 (100 at a tenth of
 * the threshold), every ten times further takes 25 off (0 at a thousand times it). Rounded
 * down, so that a score shown as 75 is always a match.
 */
export function matchScore(difference: number, threshold: number): number {
  if (difference <= 0) return 100;
  const score = MATCH_SCORE - 25 * Math.log10(difference / threshold);
  return Math.min(100, Math.max(0, Math.floor(score)));
}
