import { Vector3 } from 'three';
import { assignContributions } from './ray-contributions.ts';
import { type RayObserver, RayTreeRecording } from './ray-recorder.ts';
import type { Ray } from './ray.ts';
import type { PixelTrace } from './ray-tree.ts';
import { renderPixel } from './render-pixel.ts';
import { TreeTally } from './ray-tree-tally.ts';
import type { TracerScene } from './tracer-scene.ts';
import { keptTrees } from './tree-budget.ts';

/**
 * Pixels `first` … `first + count − 1` of the camera's screen with about `budget` of their
 * rays, all of pixel `keepPixel`'s (counted from `first`, or null): exactly what
 * `thinTraces(tracePixels(scene, first, count, seed), budget, keepPixel)` gives
 * (tree-budget.ts), without recording the trees it leaves out. The lab's worker sends a
 * budget of the trees while the learner edits; with the free lab's largest settings (108,836
 * rays a screen) recording every tree took several times as long as the colours, on the
 * core the page shares (docs/benchmark-log.md).
 *
 * Two passes: the first traces every pixel and only counts its trees (ray-tree-tally.ts), so
 * the rule chooses from the same sizes and kinds; the second traces again only the chosen
 * trees (about 1 in 70 with those settings), and records them. Every random number is keyed by its pixel
 * sample (estimator.ts) and a recorded tree's shadow rays find the nearest blocker
 * whatever was traced before (shadow-tester.ts), so a tree comes out the same in either pass.
 *
 * `oneSample` (a screen known to be heavy, while the learner edits): every pixel but
 * `keepPixel` is traced with one of its supersamples only (middleSample), its colour that
 * sample's, and the rule chooses among that sample's trees; its other samples are neither
 * traced nor counted (PixelTrace.onlySample). Counting every ray only to leave nearly all of
 * them out kept a core busy for the whole of a drag (docs/benchmark-log.md, issue 38). Path
 * mode records no trees and is traced whole.
 */
export function tracePixelsWithinBudget(
  scene: TracerScene,
  first: number,
  count: number,
  seed: number,
  budget: number,
  keepPixel: number | null,
  oneSample = false,
): PixelTrace[] {
  const [width, height] = scene.source.camera.pixels;
  const at = (i: number): [number, number] => [(first + i) % width, Math.floor((first + i) / width)];
  const sampled = oneSample && scene.settings.integrator !== 'path';
  const only = (i: number): number | undefined => (sampled && i !== keepPixel ? middleSample(scene.settings.supersampling) : undefined);
  const tally = new TreeTally();
  const colors: [number, number, number][] = [];
  const color = new Vector3();
  for (let i = 0; i < count; i++) {
    tally.pixelNow = i;
    renderPixel(scene, ...at(i), width, height, seed, color, tally, undefined, only(i));
    colors.push([Math.fround(color.x), Math.fround(color.y), Math.fround(color.z)]);
  }
  const keep = keptTrees(tally, budget, keepPixel);
  // Per pixel: its first tree, the rays it traced and those kept.
  const firstTree = new Int32Array(count + 1).fill(tally.count);
  const traced = new Int32Array(count);
  const sent = new Int32Array(count);
  for (let t = tally.count - 1; t >= 0; t--) {
    const p = tally.pixel(t);
    firstTree[p] = t;
    traced[p] += tally.size(t);
    if (keep[t]) sent[p] += tally.size(t);
  }
  // Every root counts 1/s² of its pixel, as in the whole tree (path mode records no trees).
  const rootShare = 1 / scene.settings.supersampling ** 2;
  const traces = new Array<PixelTrace>(count);
  for (let i = 0; i < count; i++) {
    const trace: PixelTrace = { pixel: at(i), color: colors[i], rays: [] };
    if (sent[i] > 0) {
      const chosen = new ChosenTrees(tally, keep, firstTree[i]);
      renderPixel(scene, ...at(i), width, height, seed, color, chosen, undefined, only(i));
      assignContributions(chosen.roots, chosen.weights, chosen.unclampedSums, rootShare);
      trace.rays = chosen.roots;
    }
    const sample = only(i);
    // A pixel traced in part is not counted: its other samples' rays are unknown.
    if (sample !== undefined) trace.onlySample = sample;
    else if (sent[i] < traced[i]) trace.traced = traced[i];
    traces[i] = trace;
  }
  return traces;
}

/** The sample at the middle of a pixel's s × s grid (row by row), which oneSample traces. */
export function middleSample(s: number): number {
  return Math.floor(s / 2) * s + Math.floor(s / 2);
}

const carriedColor = new Vector3();

/**
 * A pixel's trees where `keep` says so (from tree `next` on, in the order renderPixel tells
 * them), the others neither traced nor recorded; a pinhole ray carries its sample's colour
 * from the tally, as its rays are not all traced.
 */
class ChosenTrees extends RayTreeRecording {
  private pinholeTree = -1;

  constructor(
    private readonly tally: TreeTally,
    private readonly keep: Uint8Array,
    private next: number,
  ) {
    super();
  }

  override skips(): boolean {
    if (this.keep[this.next]) return false;
    this.next++;
    return true;
  }

  override sampleRay(ray: Ray): RayObserver | null {
    this.next++;
    return super.sampleRay(ray);
  }

  // A pinhole ray left out leaves out its rays too (the rule keeps a kept tree's parent).
  override pinholeRay(ray: Ray, focalLength: number): void {
    this.pinholeTree = this.next++;
    if (this.keep[this.pinholeTree]) super.pinholeRay(ray, focalLength);
  }

  override lensRay(ray: Ray, lensPoint: Vector3, time: number, weight: number): RayObserver | null {
    this.next++;
    return super.lensRay(ray, lensPoint, time, weight);
  }

  override sampleDone(color: Vector3): void {
    const carried = this.tally.pinholeColor(this.pinholeTree);
    super.sampleDone(carried ? carriedColor.fromArray(carried) : color);
    this.pinholeTree = -1;
  }
}
