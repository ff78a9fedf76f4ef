import type { Scene } from '../../../scene/scene.ts';
import { hashKey } from '../../../tracer/sampler.ts';
import { buildTracerScene } from '../../../tracer/tracer-scene.ts';
import type { Vec3 } from '../code-lab-grading.ts';
import { tracerCosineDirection } from '../cosine-bounce-lab.ts';
import { isFiniteVector, UNIT_LENGTH_TOLERANCE } from '../direction-statistics.ts';
import { renderBouncePaths, type Bounce } from './bounce-path-renderer.ts';
import type { AskLearner } from './render-passes.ts';

/** Paths per pixel of the cosine lab's render, in both pictures. */
export const COSINE_RENDER_PATHS = 16;

/**
 * Directions asked of a function for each normal the paths meet. Asking once per bounce would
 * be about 200 000 calls for a 64 × 64 render, far too many to copy to the sandbox and back;
 * each bounce takes one of these instead, picked by the path's random numbers. 2048 keep the
 * mean brightness of a correct function within about 3 % of the tracer's.
 */
export const DIRECTIONS_PER_NORMAL = 2048;

/** Passes at most: new normals are met only when a function sends paths where the tracer's did not (e.g. onto a back face). */
const MAX_PASSES = 4;

/** What the cosine lab's render came to: the two images, or why the learner's one could not be made. */
export type CosineRenderResult =
  | { kind: 'rendered'; mine: Float32Array; reference: Float32Array }
  /** An answer the render cannot use: the call's normal and what came back (not a vector of finite numbers, or not of length 1). */
  | { kind: 'bad-answer'; normal: Vec3; problem: { kind: 'not-a-vector'; threw: string | null } | { kind: 'not-unit'; direction: Vec3; length: number } }
  | { kind: 'too-many-passes'; passes: number }
  | { kind: 'no-answers'; reason: unknown };

/** A normal as a table's key: the same surface's normal may differ in its last bits from hit to hit. */
const normalKey = ({ x, y, z }: Vec3) => `${x.toFixed(6)},${y.toFixed(6)},${z.toFixed(6)}`;

/**
 * A function's directions around each normal, DIRECTIONS_PER_NORMAL of them, asked in one
 * batch per pass; each bounce draws one number to pick one. A bounce at a normal not asked
 * yet is noted and takes the tracer's direction for now (the tracer's own picture is made so,
 * with the table empty). Normals are numbered in the order they are first met; call i at
 * normal k gets the seed hashKey(seed, k, i).
 */
class DirectionTable {
  private readonly directions = new Map<string, Vec3[]>();
  readonly missed = new Map<string, Vec3>();

  constructor(private readonly seed: number) {}

  readonly bounce: Bounce = (normal, random) => {
    const key = normalKey(normal);
    const known = this.directions.get(key);
    const pick = random();
    if (known) return known[Math.floor(pick * known.length)]!;
    if (!this.missed.has(key)) this.missed.set(key, normal);
    return tracerCosineDirection(normal, random);
  };

  /** The calls for the missed normals: (normal, { seededRandom }) each. */
  calls(): [Vec3, { seededRandom: number }][] {
    const first = this.directions.size;
    return [...this.missed.values()].flatMap((normal, k) =>
      Array.from({ length: DIRECTIONS_PER_NORMAL }, (_, i): [Vec3, { seededRandom: number }] => [normal, { seededRandom: hashKey(this.seed, first + k, i) }]),
    );
  }

  /** Fills in the missed normals' directions, in the order of calls(). */
  learn(directions: readonly Vec3[]): void {
    [...this.missed.keys()].forEach((key, k) => this.directions.set(key, directions.slice(k * DIRECTIONS_PER_NORMAL, (k + 1) * DIRECTIONS_PER_NORMAL)));
    this.missed.clear();
  }
}

/**
 * Renders the level's scene with the learner's `cosineDirection` for every diffuse bounce
 * (bounce-path-renderer.ts) beside the same render with the tracer's `sampleHemisphere`,
 * COSINE_RENDER_PATHS paths per pixel, the paths' other random numbers shared. The
 * tracer's picture takes its own direction at every bounce; the learner's takes one of its
 * function's DIRECTIONS_PER_NORMAL directions for the bounce's normal (DirectionTable). Light
 * sampling is left out, whatever the scene says: then every bit of light a path brings
 * comes through its bounces, so a function with another density than cos θ / π changes the
 * mean brightness, not only the noise. The learner's code runs only in the sandbox.
 */
export async function renderCosineWithLearner(source: Scene, ask: AskLearner, width: number, height: number, seed: number): Promise<CosineRenderResult> {
  const scene = buildTracerScene(
    { ...source, objects: source.objects.filter((object) => object.shape !== 'mesh'), settings: { ...source.settings, lightSampling: false } },
    new Map(),
  );
  // The tracer's picture takes its own direction at every bounce; on the way it notes the normals the paths meet.
  const table = new DirectionTable(seed);
  const reference = await renderBouncePaths(scene, table.bounce, width, height, COSINE_RENDER_PATHS, seed);
  for (let pass = 1; pass <= MAX_PASSES; pass++) {
    const calls = table.calls();
    const reply = await ask(calls);
    if ('reason' in reply) return { kind: 'no-answers', reason: reply.reason };
    const directions: Vec3[] = [];
    for (const [index, [normal]] of calls.entries()) {
      const outcome = reply.outcomes[index] ?? { threw: 'no answer', line: null };
      const value = 'returned' in outcome ? outcome.returned : undefined;
      if (!isFiniteVector(value)) return { kind: 'bad-answer', normal, problem: { kind: 'not-a-vector', threw: 'threw' in outcome ? outcome.threw : null } };
      const length = Math.hypot(value.x, value.y, value.z);
      if (Math.abs(length - 1) > UNIT_LENGTH_TOLERANCE) return { kind: 'bad-answer', normal, problem: { kind: 'not-unit', direction: value, length } };
      directions.push({ x: value.x, y: value.y, z: value.z });
    }
    table.learn(directions);
    const mine = await renderBouncePaths(scene, table.bounce, width, height, COSINE_RENDER_PATHS, seed);
    if (table.missed.size === 0) return { kind: 'rendered', mine, reference };
  }
  return { kind: 'too-many-passes', passes: MAX_PASSES };
}

/** A picture's mean brightness as shown: the mean of its linear values (all pixels, all channels) times 2^exposure. */
export function meanBrightness(image: Float32Array, exposure: number): number {
  let sum = 0;
  for (const value of image) sum += value;
  return (sum / image.length) * 2 ** exposure;
}
