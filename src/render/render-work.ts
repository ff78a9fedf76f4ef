/**
 * How far a render is, in rays: the progress a pass reports and the time it has left.
 *
 * A pass's progress is the rays its returned tiles traced (the workers count them) over
 * those plus the rays its other tiles are predicted to take (ray-cost-map.ts). When a tile
 * comes back, its prediction leaves the remainder and its real rays join the done ones, so
 * the fraction done / (done + remaining) never falls, whatever the tile really cost: it rises
 * by a·r + d·p ≥ 0 over a positive denominator (done d, remaining r, the tile's rays a and its
 * prediction p ≤ r). It reaches 1 with the pass's last tile and not before.
 *
 * The time left is given in the final pass, which is most of the render: its predicted rays
 * left (in path mode with those of the final passes after it, path-passes.ts) at the rate it
 * has traced rays since its first tile came back (wall clock, all workers together).
 * Counting from the render's start took in the workers' scene build (a render once said
 * "about 4 h left" for 45 s); counting the sharp pass took in a pass that traced fewer rays
 * a second (in one browser render 1.0 million against the final pass's 1.46 million: one
 * sample a pixel in tiles painted one by one), and said "about 2 min left" 60 s before the
 * end.
 */
import type { RayStats } from '../tracer/ray-tree.ts';
import type { Tile } from '../tracer/tile.ts';
import { RayCostMap, type RayCostSnapshot } from './ray-cost-map.ts';
import type { RenderPass } from './render-passes.ts';

/** Until this long after the final pass's first tile, its rate says too little (a few tiles) to give a time. */
const SECONDS_BEFORE_TIME_LEFT = 2;

/** The smallest rest of a pass before its last tile, as a share of its done rays. */
const REST_FLOOR = 1e-6;

/** A pass's samples per pixel: s² in the final pass, one per block² in a preview. */
function samplesPerPixel({ block, samplesPerPixel }: Pick<RenderPass, 'block' | 'samplesPerPixel'>): number {
  return samplesPerPixel / block ** 2;
}

export function raysOf(stats: RayStats): number {
  return stats.primary + stats.shadow + stats.reflect + stats.refract;
}

/** What a progress report says of the pass and the render's time. */
export interface WorkDone {
  /** Rays traced in the pass so far. */
  done: number;
  /** Those and the rays predicted for the pass's tiles not back yet: equal to `done` only when the pass is complete. */
  total: number;
  /** The render's seconds left at the final pass's rate, or null before the final pass's first seconds. */
  secondsLeft: number | null;
}

export class RenderWork {
  /** Rays traced in every pass. */
  rays = 0;
  private readonly map: RayCostMap;
  /** When the final pass's first tile came back, and the rays traced by then: the rate counts from there. */
  private clock: { at: number; rays: number } | null = null;
  private snapshot: RayCostSnapshot;
  private pass: RenderPass | undefined;
  private passDone = 0;
  private passRemaining = 0;
  /** Samples per pixel of the final passes after the current one (path mode's progressive passes), by pass index. */
  private readonly laterSamples: number[];
  /** The rays those later passes are predicted to take. */
  private laterRays = 0;

  constructor(
    width: number,
    height: number,
    private readonly passes: RenderPass[],
    assumedRaysPerSample: number,
  ) {
    this.map = new RayCostMap(width, height, assumedRaysPerSample);
    this.laterSamples = passes.map((_, index) => passes.slice(index + 1).reduce((sum, pass) => sum + (pass.kind === 'final' ? samplesPerPixel(pass) : 0), 0));
    this.snapshot = this.map.snapshot();
    this.startPass(0);
  }

  /** The pass at `index` begins: it is predicted with the map as it is now. */
  startPass(index: number): void {
    this.pass = this.passes[index];
    this.snapshot = this.map.snapshot();
    this.passDone = 0;
    this.passRemaining = this.pass ? this.snapshot.predictImage(samplesPerPixel(this.pass)) : 0;
    // The prediction is linear in the samples: one image's worth of a sample, times theirs.
    this.laterRays = this.pass ? this.snapshot.predictImage(1) * this.laterSamples[index] : 0;
  }

  /** A tile of the current pass came back with `samples` traced; `last`: the pass's last tile. */
  tileBack(tile: Tile, samples: number, stats: RayStats, last: boolean): WorkDone {
    const rays = raysOf(stats);
    this.rays += rays;
    this.map.record(tile, samples, rays);
    this.passDone += rays;
    const predicted = this.pass ? this.snapshot.predict(tile, samplesPerPixel(this.pass)) : 0;
    // Rounding may leave the predictions' sum a hair off the pass's, and a tile may cost more
    // than all the pass's predicted rest: only the last tile empties the rest, so that no
    // earlier report reads 100 % (a floor of a millionth of the done rays keeps the fraction
    // rising, as the proof above needs the rest to shrink by the prediction or stay put).
    this.passRemaining = last ? 0 : Math.max(this.passRemaining - predicted, this.passDone * REST_FLOOR, Number.MIN_VALUE);
    return { done: this.passDone, total: this.passDone + this.passRemaining, secondsLeft: this.secondsLeft() };
  }

  private secondsLeft(): number | null {
    if (this.pass?.kind !== 'final') return null;
    const now = performance.now();
    this.clock ??= { at: now, rays: this.rays };
    const seconds = (now - this.clock.at) / 1000;
    const rays = this.rays - this.clock.rays;
    if (seconds < SECONDS_BEFORE_TIME_LEFT || rays <= 0) return null;
    return ((this.passRemaining + this.laterRays) * seconds) / rays;
  }
}
