/**
 * The ray trees of one traced screen, flattened once into typed arrays in depth-first
 * (pre-order) order, so the visibility rules (ray-visibility.ts) run as one linear pass
 * over compact memory on every option change instead of chasing 50k scattered node
 * objects: at 50k rays the tree walk is memory-bound (each node is five small objects),
 * and the flat pass is ~10× faster. A subtree is the index range [i, subtreeEnd[i]), so
 * hiding a ray with its descendants is one jump.
 */
import type { ScreenRays } from '../render/screen-rays.ts';
import type { RayNode, RayType } from '../tracer/ray-tree.ts';
import { type GlossyCone, glossyCones } from './glossy-cone.ts';
import { RAY_COLOR_KEY_INDEX as KEY_INDEX, rayColorKey } from './ray-palette.ts';

/** A ray that hits nothing is drawn this long, in metres (spec §3). */
export const MISS_LENGTH = 10;

/** A copy of `array` with room for `length` elements (its contents kept). */
export function resized<T extends Float32Array | Float64Array | Uint8Array | Int32Array>(array: T, length: number): T {
  const bigger = new (array.constructor as new (length: number) => T)(length);
  bigger.set(array);
  return bigger;
}

function isShadow(type: RayType): boolean {
  return type === 'shadow' || type === 'area-shadow';
}

export class FlatRays {
  count = 0;
  origin = new Float32Array(0);
  direction = new Float32Array(0);
  /** Metres drawn: the node's length, or MISS_LENGTH for a miss. */
  length = new Float32Array(0);
  /**
   * The share of its pixel the rules judge a ray by (64-bit, so a share equal to the
   * threshold compares equal): its own contribution, except that a
   * shadow ray (which carries black, so 0 by definition) takes its parent's.
   */
  contribution = new Float64Array(0);
  /** Metres of travel from the camera before it starts to grow: its parent's start + length. */
  start = new Float32Array(0);
  hit = new Uint8Array(0);
  /** Index into RAY_COLOR_KEYS. */
  colorKey = new Uint8Array(0);
  /** The index after its last descendant. */
  subtreeEnd = new Int32Array(0);
  /** The shutter time τ of the ray's lens/time ancestor (or its own), −1 for none. */
  time = new Float32Array(0);
  /** Index into `corners` / 12 for a merged area node drawn as a cone, else −1. */
  cone = new Int32Array(0);
  /** The light corners of each cone, 12 floats per cone. */
  corners = new Float32Array(0);
  coneCount = 0;
  readonly nodes: RayNode[] = [];
  /** Pixel p's rays are [pixelStart[p], pixelStart[p + 1]); pixel p = y · columns + x. */
  readonly pixelStart: Int32Array;

  /** `mergeGlossy`: draw a glossy fan of more than 25 rays on one object as one cone (the ray debugger steps through every ray, so it keeps them). */
  constructor(
    readonly columns: number,
    readonly rows: number,
    private readonly mergeGlossy = true,
  ) {
    this.pixelStart = new Int32Array(columns * rows + 1);
  }

  /** Appends `node` and its subtree; returns nothing, fills subtreeEnd on the way back. */
  add(node: RayNode, parentContribution: number, start: number, parentTime = -1): void {
    const i = this.grow();
    this.nodes.push(node);
    const { origin, direction } = node;
    // Component by component: TypedArray.set from a plain array is several times slower.
    this.origin[i * 3] = origin[0];
    this.origin[i * 3 + 1] = origin[1];
    this.origin[i * 3 + 2] = origin[2];
    this.direction[i * 3] = direction[0];
    this.direction[i * 3 + 1] = direction[1];
    this.direction[i * 3 + 2] = direction[2];
    const length = node.hit ? node.length : MISS_LENGTH;
    const contribution = isShadow(node.type) ? parentContribution : node.contribution;
    this.length[i] = length;
    this.contribution[i] = contribution;
    this.start[i] = start;
    this.hit[i] = node.hit ? 1 : 0;
    this.colorKey[i] = KEY_INDEX[rayColorKey(node.type, node.hit, node.untested === true)];
    const time = node.time ?? parentTime;
    this.time[i] = time;
    this.cone[i] = node.corners && (node.type === 'area-light' || node.type === 'area-shadow') ? this.addCone(node.corners) : -1;
    this.addChildren(node.children, contribution, start + length, time);
    this.subtreeEnd[i] = this.count;
  }

  /** Appends `children` and their subtrees; a glossy fan drawn as a cone (glossy-cone.ts) goes in as one entry. */
  private addChildren(children: readonly RayNode[], contribution: number, start: number, time: number): void {
    const cones = this.mergeGlossy ? glossyCones(children) : null;
    for (let k = 0; k < children.length; k++) {
      const child = children[k];
      const cone = cones?.get(child);
      if (cone) this.addGlossyCone(cone, start, time);
      else if (!cones || !inCone(child, cones)) this.add(child, contribution, start, time);
    }
  }

  /** One entry for the fan, its rays' own children under it, each starting where its ray arrives. */
  private addGlossyCone({ node, corners }: GlossyCone, start: number, time: number): void {
    const i = this.grow();
    this.nodes.push(node);
    for (let axis = 0; axis < 3; axis++) {
      this.origin[i * 3 + axis] = node.origin[axis];
      this.direction[i * 3 + axis] = node.direction[axis];
    }
    this.length[i] = node.length;
    this.contribution[i] = node.contribution;
    this.start[i] = start;
    this.hit[i] = 1;
    this.colorKey[i] = KEY_INDEX[rayColorKey(node.type, true)];
    this.time[i] = time;
    this.cone[i] = this.addCone(corners);
    for (const ray of node.children) this.addChildren(ray.children, ray.contribution, start + ray.length, time);
    this.subtreeEnd[i] = this.count;
  }

  private addCone(corners: NonNullable<RayNode['corners']>): number {
    const c = this.coneCount++;
    if (this.corners.length < this.coneCount * 12) this.corners = resized(this.corners, Math.max(12 * 16, this.corners.length * 2));
    for (let k = 0; k < 4; k++) this.corners.set(corners[k], c * 12 + k * 3);
    return c;
  }

  /** One more slot, doubling the arrays when full. */
  private grow(): number {
    const i = this.count++;
    if (i < this.length.length) return i;
    const capacity = Math.max(256, this.length.length * 2);
    this.origin = resized(this.origin, capacity * 3);
    this.direction = resized(this.direction, capacity * 3);
    this.length = resized(this.length, capacity);
    this.contribution = resized(this.contribution, capacity);
    this.start = resized(this.start, capacity);
    this.hit = resized(this.hit, capacity);
    this.colorKey = resized(this.colorKey, capacity);
    this.subtreeEnd = resized(this.subtreeEnd, capacity);
    this.cone = resized(this.cone, capacity);
    this.time = resized(this.time, capacity);
    return i;
  }
}

/** A ray of a fan drawn as one of `cones` (it is one of their nodes' children). */
function inCone(ray: RayNode, cones: ReadonlyMap<RayNode, GlossyCone>): boolean {
  for (const cone of cones.values()) if (cone.node.children.includes(ray)) return true;
  return false;
}

/** Flattened once per ScreenRays object (they are never mutated: a new trace is a new object), with and without glossy cones. */
const flattened = { true: new WeakMap<ScreenRays, FlatRays>(), false: new WeakMap<ScreenRays, FlatRays>() };

export function flattenRays(rays: ScreenRays, glossyCones = true): FlatRays {
  const cache = flattened[`${glossyCones}`];
  let flat = cache.get(rays);
  if (flat) return flat;
  flat = new FlatRays(rays.columns, rays.rows, glossyCones);
  const pixels = rays.columns * rays.rows;
  for (let p = 0; p < pixels; p++) {
    flat.pixelStart[p] = flat.count;
    const roots = rays.traces[p]?.rays ?? [];
    for (const root of roots) flat.add(root, root.contribution, 0);
  }
  flat.pixelStart[pixels] = flat.count;
  cache.set(rays, flat);
  return flat;
}
