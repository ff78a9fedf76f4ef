import type { Vector3 } from 'three';
import type { Color } from '../scene/scene.ts';
import type { TracerLight } from './lights.ts';
import { mergesSamples, type PixelRecording, type RayObserver } from './ray-recorder.ts';
import type { RayType } from './ray-tree.ts';
import { type BudgetTrees, RAY_KIND_COUNT, rayKind } from './tree-budget.ts';

/**
 * A block of pixels' ray trees as the budget's rule sees them (tree-budget.ts), counted
 * while renderPixel traces them, with no ray recorded: per tree its rays, the kinds among
 * them, its parent and its pixel. It counts the rays a RayTreeRecording would record, from the
 * same calls (an area light's agreeing samples as one cone), so the rule keeps the same trees
 * from it as from the recorded ones, and only those need recording (trace-within-budget.ts).
 */
export class TreeTally implements PixelRecording, BudgetTrees {
  /** The pixel whose trees renderPixel tells next, counted from the block's first. */
  pixelNow = 0;
  readonly kindCount = RAY_KIND_COUNT;
  private readonly sizes: number[] = [];
  /** Per tree, bit k set when it has a ray of kind k (there are fewer than 32). */
  private readonly masks: number[] = [];
  private readonly parents: number[] = [];
  private readonly pixels: number[] = [];
  /** The tree of the sample's pinhole ray, while its lens or shutter rays are told; else −1. */
  private pinhole = -1;
  /** What each pinhole ray carries (its sample's colour), by its tree. */
  private readonly pinholeColors = new Map<number, Color>();

  get count(): number {
    return this.sizes.length;
  }

  size(t: number): number {
    return this.sizes[t];
  }

  pixel(t: number): number {
    return this.pixels[t];
  }

  parent(t: number): number {
    return this.parents[t];
  }

  kinds(t: number, visit: (kind: number) => void): void {
    for (let mask = this.masks[t], kind = 0; mask !== 0; mask >>>= 1, kind++) if (mask & 1) visit(kind);
  }

  /** Adds `rays` rays of the kinds in `mask` to the tree being traced (the last one). */
  addRays(rays: number, mask: number): void {
    const t = this.sizes.length - 1;
    this.sizes[t] += rays;
    this.masks[t] |= mask;
  }

  sampleRay(): RayObserver {
    this.startTree(-1);
    return new RayTally(this, 'primary');
  }

  pinholeRay(): void {
    this.startTree(-1);
    // The pinhole ray is recorded as hit, at the plane in focus (render-pixel.ts).
    this.addRays(1, 1 << rayKind('primary', true, false));
    this.pinhole = this.sizes.length - 1;
  }

  lensRay(): RayObserver {
    this.startTree(this.pinhole);
    return new RayTally(this, 'primary');
  }

  /** What the pinhole ray of tree `t` carries. */
  pinholeColor(t: number): Color | undefined {
    return this.pinholeColors.get(t);
  }

  sampleDone(color: Vector3): void {
    if (this.pinhole >= 0) this.pinholeColors.set(this.pinhole, color.toArray());
    this.pinhole = -1;
  }

  skips(): boolean {
    return false;
  }

  private startTree(parent: number): void {
    this.sizes.push(0);
    this.masks.push(0);
    this.parents.push(parent);
    this.pixels.push(this.pixelNow);
  }
}

/** Counts one primary, reflected or refracted ray and the light rays of its hit, as RayRecorder would record them. */
class RayTally implements RayObserver {
  /** The samples of the light being shaded: how many, the kinds among them, the first one's type and whether all share it. */
  private samples = 0;
  private sampleKinds = 0;
  private firstType: RayType | null = null;
  private firstUntested = false;
  private agree = true;

  constructor(
    private readonly tally: TreeTally,
    private readonly type: 'primary' | 'reflect' | 'refract',
  ) {}

  miss(): void {
    this.tally.addRays(1, 1 << rayKind(this.type, false, false));
  }

  hit(): void {
    this.tally.addRays(1, 1 << rayKind(this.type, true, false));
  }

  startLight(): void {
    this.samples = 0;
    this.sampleKinds = 0;
    this.firstType = null;
    this.firstUntested = false;
    this.agree = true;
  }

  blocked(): void {
    this.sample('shadow', false);
  }

  reached(
    _attenuation: number,
    _nDotL: number,
    _rDotV: number,
    _from: Vector3,
    _toLight: Vector3,
    _distance: number,
    _lightId: string,
    _d: Color,
    _s: Color,
    untested: boolean,
  ): void {
    this.sample('light', untested);
  }

  finishLight(light: TracerLight): void {
    if (this.samples === 0) return;
    if (!mergesSamples(light, this.agree)) this.tally.addRays(this.samples, this.sampleKinds);
    else this.tally.addRays(1, 1 << rayKind(this.firstType === 'light' ? 'area-light' : 'area-shadow', true, this.firstUntested));
  }

  /** The child is counted when it ends (miss or hit), with whether it hit. */
  child(type: 'reflect' | 'refract'): RayObserver {
    return new RayTally(this.tally, type);
  }

  absorbed(type: 'reflect' | 'refract'): void {
    // An absorbed glossy ray is recorded as hit, at length 0.
    this.tally.addRays(1, 1 << rayKind(type, true, false));
  }

  // Nothing else a recorder keeps changes the count or the kinds.
  ambient(): void {}
  noRay(): void {}
  depthLimited(): void {}
  childTerm(): void {}
  markGlossy(): void {}

  private sample(type: 'shadow' | 'light', untested: boolean): void {
    if (this.samples === 0) {
      this.firstType = type;
      this.firstUntested = untested;
    } else if (type !== this.firstType) this.agree = false;
    this.samples++;
    this.sampleKinds |= 1 << rayKind(type, true, untested);
  }
}
