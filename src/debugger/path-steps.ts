/**
 * The path debugger's numbers (path-tracing spec §5): one recorded path (path-recorder.ts)
 * written out vertex by vertex as the rendering equation's estimate, L = Le + f·cosθ·Li/pdf,
 * unrolled along the path (Kajiya 1986; pbrt-v4 §13.1): at each vertex what the bounce
 * multiplied the throughput by, the throughput so far, what light sampling and light seen
 * directly added, and the path's running sum, which ends at its contribution. Pure: the
 * debugger shows these, and tests check them against the paths the tracer recorded.
 */
import type { Color } from '../scene/scene.ts';
import type { PathEvent, PathVertex, RecordedPath } from '../tracer/path-recorder.ts';
import { rouletteSurvival } from '../tracer/roulette-survival.ts';

/** One vertex of a path, as the debugger shows it. */
export interface PathVertexRow {
  event: PathEvent;
  objectId: string | null;
  lightId: string | null;
  /** cosθ between the normal and the sampled direction (a diffuse bounce), else null. */
  cosTheta: number | null;
  /** The sampled direction's density per steradian (a diffuse bounce), else null. */
  pdf: number | null;
  /**
   * What this vertex multiplied the throughput by: f·cosθ/pdf over the chance of the lobe it
   * picked (a mirror: ks over its chance; glass: 1). Null where nothing was multiplied.
   */
  factor: Color | null;
  /** Russian roulette here: the chance the path had to go on (its throughput was divided by it), or null. */
  survival: number | null;
  /** The throughput after this vertex (after the roulette's weight): what a unit of light along the next segment adds to the pixel. */
  throughput: Color;
  /** Light sampling here: each light's shadow ray, visible or blocked, and what it added. */
  lightSamples: PathVertex['lightSamples'];
  /** Light seen directly at this vertex (an emitter's lit side, or the background), times the throughput that reached it. */
  emitted: Color;
  /** The path's sum so far: every light sample and emission up to this vertex. */
  runningSum: Color;
}

/** The settings the rows depend on. */
export interface PathStepSettings {
  russianRoulette: boolean;
}

const ZERO: Color = [0, 0, 0];

/**
 * The rows of `path`. The tracer records each vertex's throughput before Russian roulette
 * (path-integrator.ts): a path still going after vertex i (i ≥ 2 bounces) whose largest
 * channel β is below 1 survived with chance √β (rouletteSurvival) and carries throughput/√β
 * on. Light samples
 * belong to the vertex where they were taken; the light seen directly at the last vertex is
 * what the contribution holds beyond them.
 */
export function pathRows(path: RecordedPath, settings: PathStepSettings): PathVertexRow[] {
  const rows: PathVertexRow[] = [];
  let carried: Color = [1, 1, 1];
  let sum: Color = ZERO;
  const last = path.vertices.length - 1;
  path.vertices.forEach((vertex, i) => {
    const scattered = vertex.direction !== null && i > 0;
    const factor = scattered ? divide(vertex.throughput, carried) : null;
    const largest = Math.max(...vertex.throughput);
    const goesOn = i < last && path.vertices[i + 1].event !== 'roulette-stop';
    const survival = scattered && settings.russianRoulette && i >= 2 && largest < 1 && goesOn ? rouletteSurvival(largest) : null;
    const throughput = survival === null ? vertex.throughput : scale(vertex.throughput, 1 / survival);
    for (const sample of vertex.lightSamples) sum = add(sum, sample.added);
    const emitted = i === last ? subtract(path.contribution, sum) : ZERO;
    sum = i === last ? path.contribution : sum;
    rows.push({
      event: vertex.event,
      objectId: vertex.objectId,
      lightId: vertex.lightId,
      cosTheta: vertex.pdf !== null && vertex.normal && vertex.direction ? dot(vertex.normal, vertex.direction) : null,
      pdf: vertex.pdf,
      factor,
      survival,
      throughput,
      lightSamples: vertex.lightSamples,
      emitted,
      runningSum: sum,
    });
    if (scattered) carried = throughput;
  });
  return rows;
}

/** The mean of the paths' contributions, as the image stores it (32-bit floats): the pixel, when they are all the pixel's paths. */
export function meanOfPaths(contributions: readonly Color[]): Color {
  const total = contributions.reduce<Color>((sum, c) => [sum[0] + c[0], sum[1] + c[1], sum[2] + c[2]], [0, 0, 0]);
  const n = Math.max(1, contributions.length);
  return [Math.fround(total[0] / n), Math.fround(total[1] / n), Math.fround(total[2] / n)];
}

function divide(a: Color, b: Color): Color {
  return [b[0] === 0 ? 0 : a[0] / b[0], b[1] === 0 ? 0 : a[1] / b[1], b[2] === 0 ? 0 : a[2] / b[2]];
}

function scale(a: Color, s: number): Color {
  return [a[0] * s, a[1] * s, a[2] * s];
}

function add(a: Color, b: Color): Color {
  return [a[0] + b[0], a[1] + b[1], a[2] + b[2]];
}

function subtract(a: Color, b: Color): Color {
  // What floating-point rounding leaves of a sum minus its parts is not light.
  const part = (x: number, y: number) => (Math.abs(x - y) <= 1e-12 * Math.max(1, Math.abs(x)) ? 0 : x - y);
  return [part(a[0], b[0]), part(a[1], b[1]), part(a[2], b[2])];
}

function dot(a: Color, b: Color): number {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
