import { Vector3 } from 'three';
import type { Color } from '../scene/scene.ts';
import type { TracerLight } from './lights.ts';
import type { Ray } from './ray.ts';
import type { RayNode, RayType } from './ray-tree.ts';
import { LightTermsRecorder, type ShadingTerms } from './shading-terms.ts';

/** Missed rays are drawn this long in the ray tree (spec §3). */
export const MISS_LENGTH = 10;

/** Area lights with at least this many samples get one merged node when all agree (spec §3). */
const MERGE_AREA_SAMPLES = 25;

const toCentre = new Vector3();

/**
 * What renderPixel tells of a pixel's camera rays, tree by tree (the trees of
 * tree-budget.ts): a sample's one ray; or, when a sample casts several (lens points, shutter
 * times), its pinhole ray and then each of them. RayTreeRecording records every tree;
 * ray-tree-tally.ts only counts their rays, and trace-within-budget.ts records the chosen ones.
 */
export interface PixelRecording {
  /** A sample's one camera ray: what observes its tree, or null when it is not recorded. */
  sampleRay(ray: Ray): RayObserver | null;
  /** A sample's pinhole ray, which meets the plane in focus at `focalLength`: the root of the rays that follow. */
  pinholeRay(ray: Ray, focalLength: number): void;
  /** One of a sample's rays from the lens point `lensPoint` at `time`, adding `weight` × its colour to the sample: its observer, or null. */
  lensRay(ray: Ray, lensPoint: Vector3, time: number, weight: number): RayObserver | null;
  /** A sample with lens points or shutter times is done; `color` is what its pinhole ray carries. */
  sampleDone(color: Vector3): void;
  /**
   * Asked before each sample's ray or lens ray is traced: true to leave its tree out
   * untraced (the pixel's colour is then not what it would be: trace-within-budget.ts knows
   * the colours already).
   */
  skips(): boolean;
}

/** A pixel's ray tree while it is traced (spec §3): its roots, and what each child adds to its parent. */
export class RayTreeRecording implements PixelRecording {
  /** One root per supersample. */
  readonly roots: RayNode[] = [];
  /** What each child adds to its parent per unit of its colour (ks, kr, kt, a lens ray's 1/(n²·k), or 1). */
  readonly weights = new Map<RayNode, number>();
  /** A hit's colour summed over its channels before clamping: what its children's shares divide (ray-contributions.ts). */
  readonly unclampedSums = new Map<RayNode, number>();
  /** The pinhole ray of the sample being traced, when its rays are its children. */
  private pinhole: RayNode | null = null;

  /** @param withTerms whether hits also get their shading terms (ray-debugger spec §1); the colours are the same either way */
  constructor(readonly withTerms = false) {}

  sampleRay(ray: Ray): RayObserver | null {
    const recorder = new RayRecorder(primaryNode(ray), this);
    this.roots.push(recorder.node);
    return recorder;
  }

  pinholeRay(ray: Ray, focalLength: number): void {
    const root = primaryNode(ray);
    root.hit = true;
    root.length = focalLength;
    this.roots.push(root);
    this.pinhole = root;
  }

  lensRay(ray: Ray, lensPoint: Vector3, time: number, weight: number): RayObserver | null {
    const recorder = new RayRecorder(primaryNode(ray), this);
    recorder.node.lensPoint = lensPoint.toArray();
    recorder.node.time = time;
    if (this.pinhole) {
      this.pinhole.children.push(recorder.node);
      this.weights.set(recorder.node, weight);
    } else this.roots.push(recorder.node);
    return recorder;
  }

  sampleDone(color: Vector3): void {
    if (this.pinhole) this.pinhole.color = color.toArray();
    this.pinhole = null;
  }

  skips(): boolean {
    return false;
  }
}

/**
 * What the Whitted integrator tells of each ray it traces, when asked to (rendering passes
 * null): RayRecorder records it in a ray tree, ray-tree-tally.ts only counts it.
 */
export interface RayObserver {
  miss(color: Vector3): void;
  ambient(color: Vector3): void;
  startLight(light: TracerLight, ambient: Color): void;
  noRay(attenuation: number, nDotL: number, rDotV: number): void;
  blocked(attenuation: number, nDotL: number, rDotV: number, from: Vector3, toLight: Vector3, length: number, blockerId: string, lightId: string): void;
  reached(
    attenuation: number,
    nDotL: number,
    rDotV: number,
    from: Vector3,
    toLight: Vector3,
    distance: number,
    lightId: string,
    diffuse: Color,
    specular: Color,
    untested: boolean,
  ): void;
  finishLight(light: TracerLight, point: Vector3, diffuse: Color, specular: Color): void;
  depthLimited(wouldContinue: boolean): void;
  child(type: 'reflect' | 'refract', origin: Vector3, direction: Vector3, weight: number): RayObserver;
  absorbed(type: 'reflect' | 'refract', point: Vector3, direction: Vector3, objectId: string | null, weight: number): void;
  childTerm(type: 'reflect' | 'refract', weight: number, color: Vector3): void;
  hit(length: number, objectId: string, normal: Vector3, sum: Color, color: Vector3): void;
  /** The ray is one of a rough surface's spread rays. */
  markGlossy(): void;
}

/**
 * Whether a light's sample rays are shown as one cone (area-light or area-shadow): an area
 * light with at least MERGE_AREA_SAMPLES samples whose rays all agree (spec §3).
 */
export function mergesSamples(light: TracerLight, allAgree: boolean): boolean {
  return light.type === 'area' && light.sampleCount >= MERGE_AREA_SAMPLES && allAgree;
}

/**
 * Records one ray of a pixel's tree while the integrator traces it: the ray's node, its hit's
 * shading terms, its light and shadow rays and its reflected or refracted children (each
 * recorded by a recorder of its own). Rendering passes null for it, so the arithmetic is the
 * same with or without one and a pixel's tree has exactly the image's colour.
 */
export class RayRecorder implements RayObserver {
  private terms: ShadingTerms | null = null;
  /** The light being shaded: its terms (with terms) and its sample rays, added at finishLight. */
  private lightTerms: LightTermsRecorder | null = null;
  private lightRays: RayNode[] = [];

  constructor(
    readonly node: RayNode,
    readonly tree: RayTreeRecording = new RayTreeRecording(),
  ) {}

  /** The ray hit nothing: it carries the background. */
  miss(color: Vector3): void {
    end(this.node, false, MISS_LENGTH, null, color);
  }

  /** The hit's ambient term ka·C, first of its terms. */
  ambient(color: Vector3): void {
    if (this.tree.withTerms) this.terms = { ambient: color.toArray(), lights: [], reflect: null, refract: null, sum: [0, 0, 0], depthLimited: false };
  }

  /** Starts a light's share: its ambient term la·Lc·C, then its samples. */
  startLight(light: TracerLight, ambient: Color): void {
    this.lightTerms = this.terms ? new LightTermsRecorder(light.id, ambient) : null;
    this.lightRays = [];
  }

  /** A sample that cast no shadow ray (the light behind the surface, outside its cone, or at the point). */
  noRay(attenuation: number, nDotL: number, rDotV: number): void {
    this.lightTerms?.sample(attenuation, nDotL, rDotV, 'none');
  }

  /** A sample whose shadow ray was blocked by `blockerId` at `length`: it adds black. */
  blocked(attenuation: number, nDotL: number, rDotV: number, from: Vector3, toLight: Vector3, length: number, blockerId: string, lightId: string): void {
    const ray = newNode('shadow', from, toLight, length, true, blockerId, lightId, [0, 0, 0]);
    if (this.lightTerms !== null) ray.parts = { diffuse: [0, 0, 0], specular: [0, 0, 0] };
    this.lightRays.push(ray);
    this.lightTerms?.sample(attenuation, nDotL, rDotV, 'blocked');
  }

  /**
   * A sample that reached the light, adding `diffuse` + `specular`; `untested`: shadows are
   * off, so no shadow ray was cast and the node only records the direction to the light.
   */
  reached(
    attenuation: number,
    nDotL: number,
    rDotV: number,
    from: Vector3,
    toLight: Vector3,
    distance: number,
    lightId: string,
    diffuse: Color,
    specular: Color,
    untested: boolean,
  ): void {
    const ray = newNode('light', from, toLight, distance, true, null, lightId, [diffuse[0] + specular[0], diffuse[1] + specular[1], diffuse[2] + specular[2]]);
    if (untested) ray.untested = true;
    if (this.lightTerms !== null) ray.parts = { diffuse, specular };
    this.lightRays.push(ray);
    this.lightTerms?.sample(attenuation, nDotL, rDotV, 'reached');
  }

  /** Ends a light's share with the sums the integrator added: its rays join the tree, merged into one cone when there are many and all agree. */
  finishLight(light: TracerLight, point: Vector3, diffuse: Color, specular: Color): void {
    const samples = this.lightRays;
    const type = samples[0]?.type;
    const allAgree = samples.length > 0 && samples.every((s) => s.type === type);
    if (!mergesSamples(light, allAgree)) this.node.children.push(...samples);
    else {
      const direction = toCentre.subVectors(light.position, point);
      const distance = direction.length();
      const color = sumOf(samples.map((s) => s.color));
      const merged = newNode(
        type === 'light' ? 'area-light' : 'area-shadow',
        point,
        direction.divideScalar(distance || 1),
        distance,
        true,
        null,
        light.id,
        color,
      );
      merged.corners = light.corners().map((c) => c.toArray()) as RayNode['corners'];
      if (this.tree.withTerms) merged.parts = { diffuse: sumOf(samples.map((s) => s.parts!.diffuse)), specular: sumOf(samples.map((s) => s.parts!.specular)) };
      if (samples[0].untested) merged.untested = true;
      this.node.children.push(merged);
    }
    if (this.terms && this.lightTerms) this.terms.lights.push(this.lightTerms.finish(diffuse, specular));
  }

  /** The hit is at the recursion depth: `wouldContinue` when its material would have reflected or refracted. */
  depthLimited(wouldContinue: boolean): void {
    if (this.terms) this.terms.depthLimited = wouldContinue;
  }

  /** A reflected or refracted ray, adding weight × its colour: its recorder. */
  child(type: 'reflect' | 'refract', origin: Vector3, direction: Vector3, weight: number): RayRecorder {
    const child = newNode(type, origin, direction, 0, false, null, null, [0, 0, 0]);
    this.node.children.push(child);
    this.tree.weights.set(child, weight);
    return new RayRecorder(child, this.tree);
  }

  markGlossy(): void {
    this.node.glossy = true;
  }

  /** A glossy direction on the wrong side of the surface: not traced, it adds black (an absorbed ray of length 0). */
  absorbed(type: 'reflect' | 'refract', point: Vector3, direction: Vector3, objectId: string | null, weight: number): void {
    const absorbed = newNode(type, point, direction, 0, true, objectId, null, [0, 0, 0]);
    absorbed.glossy = true;
    absorbed.absorbed = true;
    this.node.children.push(absorbed);
    this.tree.weights.set(absorbed, weight);
  }

  /**
   * What a reflected or refracted child added. A rough surface's m² spread rays add up to
   * one term: their weights summed, their colour the weighted mean (weight × colour is then
   * what they add together, up to rounding).
   */
  childTerm(type: 'reflect' | 'refract', weight: number, color: Vector3): void {
    const terms = this.terms;
    if (!terms) return;
    const before = terms[type];
    if (!before) {
      terms[type] = { weight, color: color.toArray() };
      return;
    }
    const total = before.weight + weight;
    terms[type] = { weight: total, color: [0, 1, 2].map((i) => (before.color[i] * before.weight + color.getComponent(i) * weight) / total) as Color };
  }

  /**
   * The ray hit a surface at `length`: `sum` is its colour before clamping (what its terms
   * add up to), `color` after; `normal` is N as the shading turned it toward the ray.
   */
  hit(length: number, objectId: string, normal: Vector3, sum: Color, color: Vector3): void {
    end(this.node, true, length, objectId, color);
    this.tree.unclampedSums.set(this.node, sum[0] + sum[1] + sum[2]);
    this.node.normal = normal.toArray();
    if (this.terms) {
      this.terms.sum = sum;
      this.node.terms = this.terms;
    }
  }
}

function primaryNode(ray: Ray): RayNode {
  return {
    type: 'primary',
    origin: ray.origin.toArray(),
    direction: ray.direction.toArray(),
    length: 0,
    hit: false,
    objectId: null,
    lightId: null,
    color: [0, 0, 0],
    contribution: 0,
    children: [],
  };
}

function newNode(
  type: RayType,
  origin: Vector3,
  direction: Vector3,
  length: number,
  hit: boolean,
  objectId: string | null,
  lightId: string | null,
  color: Color,
): RayNode {
  return { type, origin: origin.toArray(), direction: direction.toArray(), length, hit, objectId, lightId, color, contribution: 0, children: [] };
}

function end(node: RayNode, hit: boolean, length: number, objectId: string | null, color: Vector3): void {
  node.hit = hit;
  node.length = length;
  node.objectId = objectId;
  node.color = color.toArray();
}

/** Colours added channel by channel, in order, from 0 (as the sample loop adds them). */
function sumOf(colors: readonly (readonly number[])[]): Color {
  return colors.reduce<Color>((sum, c) => [sum[0] + c[0], sum[1] + c[1], sum[2] + c[2]], [0, 0, 0]);
}
