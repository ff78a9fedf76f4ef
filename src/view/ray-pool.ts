/**
 * The drawn rays: one InstancedMesh of ribbons for every ray (each placed by a unit
 * cylinder's matrix, and turned to the eye by its shader) and one of unit
 * pyramids for the cones (merged area-light rays, wide glossy fans), so drawing 50k rays takes the same two draw
 * calls as drawing 10 (DESIGN.md: "the view draws, it does not decide" — the rules are in
 * ray-visibility.ts). Per instance: a matrix (position, axis, radius, length), a colour,
 * an alpha and the growth animation's (start, length) (ray-shader.ts).
 *
 * Buffers are pooled: they grow by doubling and never shrink, and an update writes only
 * the instances in use (mesh.count) and uploads only that range.
 */
import { BufferGeometry, Float32BufferAttribute, Group, InstancedBufferAttribute, InstancedMesh, type Material, type Raycaster, type Vector3 } from 'three';
import type { RayViewOptions } from '../lab-state/lab-state.ts';
import type { ScreenRays } from '../render/screen-rays.ts';
import { focusedRays, type RayFocus, screenOf } from './ray-focus.ts';
import type { RayHover, RayLayer } from './ray-layer.ts';
import { RayExtras } from './ray-extras.ts';
import {
  ALPHA_ATTRIBUTE,
  ARROW_AT_ATTRIBUTE,
  arrowAt,
  createRayMaterial,
  DASH_ATTRIBUTE,
  FULLY_GROWN,
  GROWTH_ATTRIBUTE,
  type TravelUniform,
  STOP_ATTRIBUTE,
  type ViewHeightUniform,
} from './ray-shader.ts';
import { DrawnRays, type RayStyle, type SegmentList, visibleRays } from './ray-visibility.ts';
import { keptRays, type Thinning, thinningOf } from './ray-budget.ts';
import { flattenRays } from './flat-rays.ts';
import { FILLED_GAP_KEYS, RAY_COLOR_KEYS, RAY_DASHES, type RayColorKey, STOPPED_KEYS } from './ray-palette.ts';
import { PATH_DASHES } from './path-dashes.ts';
import { SamplingLobeMesh } from './sampling-lobe-mesh.ts';
import { timeStripe } from './time-colors.ts';

/** Instances allocated at first; the buffers double from there as needed. */
const INITIAL_CAPACITY = 256;

/** Floats per instance: matrix 16, colour 3, alpha 1, growth 2; a cylinder adds its dash 2, arrowhead place 1 and stop 1. */
const FLOATS_PER_CONE = 22;
const FLOATS_PER_CYLINDER = FLOATS_PER_CONE + 4;

/**
 * RAY_DASHES as (dash, gap) pairs by colour-key index, the form SegmentList.colorKey holds: a
 * rebuild copies two numbers per ray from it. Looking each pattern up by its name and copying
 * it with TypedArray.set was a third of a 10k-ray rebuild.
 */
const DASHES_BY_KEY = dashesByKey(RAY_DASHES);

/** PATH_DASHES in the same form: a pixel's sample paths (path-dashes.ts). */
const PATH_DASHES_BY_KEY = dashesByKey(PATH_DASHES);

/** Patterns by key as (dash, gap) pairs by colour-key index; a filled gap is stored negative (ray-shader.ts aDash). */
function dashesByKey(dashes: Readonly<Record<RayColorKey, readonly [number, number]>>): Float32Array {
  return Float32Array.from(RAY_COLOR_KEYS.flatMap((key) => (FILLED_GAP_KEYS.has(key) ? [dashes[key][0], -dashes[key][1]] : dashes[key])));
}

/** Where each key's arrowhead sits (ray-shader.ts arrowAt), by colour-key index like DASHES_BY_KEY. */
const ARROW_AT_BY_KEY = Float32Array.from(RAY_COLOR_KEYS.map(arrowAt));

/** 1 for the keys with a stop plate at their end (STOPPED_KEYS), by colour-key index. */
const STOP_BY_KEY = Float32Array.from(RAY_COLOR_KEYS.map((key) => (STOPPED_KEYS.has(key) ? 1 : 0)));

/**
 * Opacity of the cones relative to the rays: a cone is a solid volume the size of the
 * light, which at full opacity would hide everything behind it.
 */
export const CONE_OPACITY = 0.2;

/**
 * Picking tolerance as an angle, in radians: the pointer counts as over a ray that passes
 * within radius + PICK_ANGLE × distance of it, i.e. about 4 px at 45° field of view on a
 * 768 px high view (45° / 768 px ≈ 0.001 rad per pixel), so 1 cm rays can be hovered from afar.
 */
export const PICK_ANGLE = 0.004;

/**
 * Seconds the finished tree stays on screen before a looping animation starts again, so
 * the student sees the whole tree before it disappears.
 */
export const LOOP_PAUSE_S = 1;

/** Names of the two meshes in RayPool.object (for tests and debugging tools). */
export const RAY_CYLINDERS_NAME = 'ray-cylinders';
export const RAY_CONES_NAME = 'ray-cones';

export interface RayPoolStats {
  /** Cylinders drawn (mesh.count). */
  rays: number;
  /** Cones drawn (area lights, wide glossy fans). */
  cones: number;
  /** Arrowheads drawn (one per ray of a chosen pixel; none for a whole screen). */
  arrows: number;
  /** Meshes that issue a draw call: at most 5 (rays, cones, and a chosen pixel's arrowheads, hidden parts and stop plates), whatever the number of rays. */
  drawCalls: number;
  /** Bytes of per-instance buffers allocated (both meshes, at their pooled capacity). */
  instanceBytes: number;
}

interface AnimationInputs {
  rays: ScreenRays | null;
  selectedPixel: readonly [number, number] | null;
  animate: boolean;
  pixelByPixel: boolean;
}

/** One instanced mesh and its capacity; replaced by a twice larger one when full. */
class InstanceBuffers {
  mesh: InstancedMesh;
  private readonly kind: 'cylinder' | 'cone';

  constructor(
    kind: 'cylinder' | 'cone',
    material: Material,
    private readonly parent: Group,
  ) {
    this.kind = kind;
    this.mesh = this.createMesh(INITIAL_CAPACITY, material);
    parent.add(this.mesh);
  }

  get capacity(): number {
    return this.mesh.instanceMatrix.count;
  }

  get alpha(): InstancedBufferAttribute {
    return this.mesh.geometry.getAttribute(ALPHA_ATTRIBUTE) as InstancedBufferAttribute;
  }

  get growth(): InstancedBufferAttribute {
    return this.mesh.geometry.getAttribute(GROWTH_ATTRIBUTE) as InstancedBufferAttribute;
  }

  get color(): InstancedBufferAttribute {
    return this.mesh.instanceColor as InstancedBufferAttribute;
  }

  /** The dash pattern by instance (cylinders only; see RAY_DASHES). */
  get dash(): InstancedBufferAttribute | undefined {
    return this.mesh.geometry.getAttribute(DASH_ATTRIBUTE) as InstancedBufferAttribute | undefined;
  }

  /** Where each instance's arrowhead sits along it (cylinders only; the arrows share it). */
  get arrowAt(): InstancedBufferAttribute | undefined {
    return this.mesh.geometry.getAttribute(ARROW_AT_ATTRIBUTE) as InstancedBufferAttribute | undefined;
  }

  /** 1 where an instance is a stopped ray with a plate at its end (cylinders only; the plates share it). */
  get stop(): InstancedBufferAttribute | undefined {
    return this.mesh.geometry.getAttribute(STOP_ATTRIBUTE) as InstancedBufferAttribute | undefined;
  }

  /** Makes room for `count` instances, replacing the mesh (and freeing its GPU buffers) when too small. */
  reserve(count: number): void {
    if (count <= this.capacity) return;
    let capacity = this.capacity;
    while (capacity < count) capacity *= 2;
    const old = this.mesh;
    this.mesh = this.createMesh(capacity, old.material as Material);
    this.parent.remove(old);
    this.parent.add(this.mesh);
    old.geometry.dispose();
    old.dispose();
  }

  /** The instance attributes (the matrix first), to copy a range of them into a piece. */
  get attributes(): InstancedBufferAttribute[] {
    return [
      this.mesh.instanceMatrix,
      this.color,
      this.alpha,
      this.growth,
      ...(this.dash ? [this.dash] : []),
      ...(this.arrowAt ? [this.arrowAt] : []),
      ...(this.stop ? [this.stop] : []),
    ];
  }

  /** Instances `from` … `to` − 1 of `source` as this mesh's first ones, drawn alone (a piece: RayPool.piece). */
  copyRange(source: InstanceBuffers, from: number, to: number): void {
    const count = Math.max(0, to - from);
    this.reserve(count);
    const targets = this.attributes;
    source.attributes.forEach((attribute, a) => {
      const size = attribute.itemSize;
      (targets[a].array as Float32Array).set((attribute.array as Float32Array).subarray(from * size, to * size));
    });
    this.commit(count);
  }

  /** Draws the first `count` instances only (those uploaded stay), or all `uploaded` of them. */
  limit(count: number, uploaded: number): void {
    this.mesh.count = Math.min(count, uploaded);
    this.mesh.visible = this.mesh.count > 0;
  }

  /** Uploads the first `count` instances and draws that many. */
  commit(count: number): void {
    this.mesh.count = count;
    this.mesh.visible = count > 0;
    if (count === 0) return;
    for (const attribute of this.attributes) {
      attribute.clearUpdateRanges();
      attribute.addUpdateRange(0, count * attribute.itemSize);
      attribute.needsUpdate = true;
    }
  }

  dispose(): void {
    this.mesh.geometry.dispose();
    this.mesh.dispose();
  }

  private createMesh(capacity: number, material: Material): InstancedMesh {
    const geometry = this.kind === 'cone' ? pyramidGeometry() : ribbonGeometry();
    geometry.setAttribute(ALPHA_ATTRIBUTE, new InstancedBufferAttribute(new Float32Array(capacity), 1));
    geometry.setAttribute(GROWTH_ATTRIBUTE, new InstancedBufferAttribute(new Float32Array(capacity * 2), 2));
    if (this.kind === 'cylinder') {
      geometry.setAttribute(DASH_ATTRIBUTE, new InstancedBufferAttribute(new Float32Array(capacity * 2), 2));
      geometry.setAttribute(ARROW_AT_ATTRIBUTE, new InstancedBufferAttribute(new Float32Array(capacity), 1));
      geometry.setAttribute(STOP_ATTRIBUTE, new InstancedBufferAttribute(new Float32Array(capacity), 1));
    }
    const mesh = new InstancedMesh(geometry, material, capacity);
    mesh.name = this.kind === 'cone' ? RAY_CONES_NAME : RAY_CYLINDERS_NAME;
    mesh.instanceColor = new InstancedBufferAttribute(new Float32Array(capacity * 3), 3);
    mesh.count = 0;
    mesh.visible = false;
    // The rays are spread over the whole scene and change every update: a bounding sphere
    // over 50k instance matrices would cost more than it ever culls.
    mesh.frustumCulled = false;
    // Hover goes through RayPool.pick; three's per-instance raycast would test 50k
    // instances whenever the view raycasts its scene to select an object.
    mesh.raycast = () => {};
    return mesh;
  }
}

/**
 * A ray's ribbon: x = ±1 across it, z from 0 to 1 along it. The vertex shader turns it to
 * face the eye at the width of the instance's cylinder (ray-shader.ts): the instances keep
 * a cylinder's matrix (axis and radius), and 2 triangles do what a six-sided cylinder's 12 did.
 */
function ribbonGeometry(): BufferGeometry {
  const positions = [-1, 0, 0, 1, 0, 0, -1, 0, 1, 1, 0, 1];
  return new BufferGeometry().setAttribute('position', new Float32BufferAttribute(positions, 3)).setIndex([0, 1, 2, 2, 1, 3]);
}

/**
 * An area cone: apex at the origin, base corners (∓1, ∓1, 1) in RayNode.corners order, so
 * one affine instance matrix maps it onto any hit point and light rectangle (or glossy fan base).
 */
function pyramidGeometry(): BufferGeometry {
  const base = [
    [-1, -1, 1],
    [1, -1, 1],
    [1, 1, 1],
    [-1, 1, 1],
  ];
  const positions: number[] = [];
  for (let k = 0; k < 4; k++) positions.push(0, 0, 0, ...base[k], ...base[(k + 1) % 4]);
  positions.push(...base[0], ...base[2], ...base[1], ...base[0], ...base[3], ...base[2]);
  return new BufferGeometry().setAttribute('position', new Float32BufferAttribute(positions, 3));
}

/** Implements RayLayer for the lab view. Call update() on every change of rays or options. */
export class RayPool implements RayLayer {
  readonly object = new Group();
  /** What contribution colour fades toward; set it to the view's background if you like. */
  style: RayStyle = { fadeTo: [0, 0, 0] };
  private readonly travel: TravelUniform = { value: FULLY_GROWN };
  /** The canvas height (CSS px) the rays are drawn into: their minimum width on screen follows it. */
  private readonly viewHeight: ViewHeightUniform = { value: 1 };
  private readonly rayMaterial = createRayMaterial('cylinder', this.travel, this.viewHeight);
  private readonly coneMaterial = createRayMaterial('cone', this.travel, this.viewHeight);
  private readonly cylinders = new InstanceBuffers('cylinder', this.rayMaterial, this.object);
  private readonly cones = new InstanceBuffers('cone', this.coneMaterial, this.object);
  private readonly arrowMaterial = createRayMaterial('arrow', this.travel, this.viewHeight);
  private readonly hiddenMaterial = createRayMaterial('hidden', this.travel, this.viewHeight);
  private readonly stopMaterial = createRayMaterial('stop', this.travel, this.viewHeight);
  private readonly extras = new RayExtras(this.object, { arrow: this.arrowMaterial, hidden: this.hiddenMaterial, stop: this.stopMaterial });
  /** A range of the instances drawn alone (`piece`), with the same materials. */
  private readonly pieceObject = new Group();
  private readonly pieceCylinders = new InstanceBuffers('cylinder', this.rayMaterial, this.pieceObject);
  private readonly pieceCones = new InstanceBuffers('cone', this.coneMaterial, this.pieceObject);
  private readonly drawn = new DrawnRays();
  /** A path vertex's sampling distribution, drawn with a pixel's sample paths (sampling-lobe-mesh.ts). */
  private readonly lobe = new SamplingLobeMesh(this.object);
  private animation: AnimationInputs = { rays: null, selectedPixel: null, animate: false, pixelByPixel: false };
  private speed = 1;
  private loop = false;
  /** Time of travel 0, set by the first tick after a (re)start; null until then. */
  private startMs: number | null = null;
  /** Travel to resume from at that first tick (keeps the rays where they were when only the speed changed). */
  private resumeTravel = 0;
  /** The ray debugger's pixel, drawn instead of the screen's rays while set (ray-focus.ts). */
  private focus: RayFocus | null = null;
  /** The most rays drawn (ray-budget.ts), or null: all of them. */
  private budget: number | null = null;
  /** How many rays the budget let through of how many, or null when all are drawn. */
  private thinned: Thinning | null = null;
  /** The last update's inputs, to draw them again under another budget. */
  private lastUpdate: Parameters<RayPool['update']> | null = null;

  constructor() {
    this.object.name = 'rays';
  }

  get stats(): RayPoolStats {
    const meshes = this.object.children.filter((child): child is InstancedMesh => child instanceof InstancedMesh);
    return {
      rays: this.cylinders.mesh.count,
      cones: this.cones.mesh.count,
      arrows: this.extras.count,
      drawCalls: meshes.filter((mesh) => mesh.visible && mesh.count > 0).length,
      instanceBytes: (this.cylinders.capacity * FLOATS_PER_CYLINDER + this.cones.capacity * FLOATS_PER_CONE) * 4,
    };
  }

  /**
   * Draws the ray debugger's pixel instead of the screen's rays from the next update() on:
   * the rays cast so far, dimmed, one highlighted (growing when just cast); null: as before.
   */
  setFocus(focus: RayFocus | null): void {
    this.focus = focus;
  }

  /** How many rays are drawn of how many while a budget leaves some out; null when all are drawn. */
  get thinning(): Thinning | null {
    return this.thinned;
  }

  get instances(): number {
    return this.drawn.rays.count + this.drawn.cones.count;
  }

  drawFirst(count: number | null): void {
    for (const { buffers, from, to } of this.inDrawOrder()) buffers.limit(count === null ? to - from : Math.max(0, count - from), to - from);
  }

  piece(from: number, count: number): Group {
    const end = Math.min(from + count, this.instances);
    const pieces = { cylinder: this.pieceCylinders, cone: this.pieceCones };
    this.inDrawOrder().forEach(({ kind, buffers, from: first, to }, order) => {
      const piece = pieces[kind];
      piece.copyRange(buffers, Math.min(Math.max(from, first), to) - first, Math.min(Math.max(end, first), to) - first);
      // In the same order as in `object`, where a boundary piece has both.
      piece.mesh.renderOrder = order;
    });
    return this.pieceObject;
  }

  /**
   * The two meshes in the order three.js draws them (both see-through, at the same place: by
   * creation, and a mesh outgrown is made again), with the instance numbers they cover.
   */
  private inDrawOrder(): { kind: 'cylinder' | 'cone'; buffers: InstanceBuffers; from: number; to: number }[] {
    const rays = this.drawn.rays.count;
    const cones = this.drawn.cones.count;
    return this.cones.mesh.id < this.cylinders.mesh.id
      ? [
          { kind: 'cone', buffers: this.cones, from: 0, to: cones },
          { kind: 'cylinder', buffers: this.cylinders, from: cones, to: cones + rays },
        ]
      : [
          { kind: 'cylinder', buffers: this.cylinders, from: 0, to: rays },
          { kind: 'cone', buffers: this.cones, from: rays, to: rays + cones },
        ];
  }

  /**
   * Chooses now, ahead of the edit that will ask for it, which rays of the screen drawn now
   * `budget` keeps (ray-budget.ts remembers it): the first edit then only draws them.
   */
  prepareBudget(budget: number): void {
    const [rays, , selectedPixel] = this.lastUpdate ?? [null, null, null];
    if (rays && !selectedPixel && !this.focus) keptRays(flattenRays(rays), budget, null);
  }

  /** Draws about `budget` rays from now on, every kind among them (ray-budget.ts); null: all. */
  setBudget(budget: number | null): void {
    if (budget === this.budget) return;
    this.budget = budget;
    if (this.lastUpdate) this.update(...this.lastUpdate);
  }

  /** Rebuilds the instances from the traced rays and the panel's options; then render a frame. */
  update(rays: ScreenRays | null, options: RayViewOptions, selectedPixel: readonly [number, number] | null): void {
    this.lastUpdate = [rays, options, selectedPixel];
    const focus = this.focus;
    // A chosen pixel is drawn alone and whole, as is the debugger's, which steps through each ray.
    const kept = !focus && !selectedPixel && rays && this.budget !== null ? keptRays(flattenRays(rays), this.budget, null) : null;
    const drawn = focus ? focusedRays(focus, options, this.drawn, this.style) : visibleRays(rays, options, selectedPixel, this.drawn, this.style, true, kept);
    this.thinned = focus ? null : thinningOf(rays, drawn, kept !== null, selectedPixel !== null);
    this.writeCylinders(drawn.rays, focus?.paths ? PATH_DASHES_BY_KEY : DASHES_BY_KEY);
    this.lobe.show(focus?.lobe ?? null);
    this.writeCones(drawn.cones);
    const oneTree = focus !== null || selectedPixel !== null;
    this.extras.update(this.cylinders.mesh, drawn.rays.count, oneTree, oneTree && anyStopped(drawn.rays));
    // Opaque rays write depth, so rays hide each other correctly; see-through ones do not,
    // so the rays behind them still show. (The material stays `transparent` either way:
    // three compiles opaque materials with alpha forced to 1, and switching compiles a new
    // program: a 528 ms long task in the e2e run on SwiftShader, mid-drag of the slider.)
    this.rayMaterial.depthWrite = !focus && (drawn.rays.count === 0 || drawn.rays.alpha[0] >= 1);
    // Paths drawn whole play like a chosen pixel's tree, from the start when they are new.
    if (focus?.animated) this.updateAnimation(screenOf(focus.trace), options, [0, 0]);
    else if (focus) this.growFocus(focus, options);
    else this.updateAnimation(rays, options, selectedPixel);
  }

  /** Sets the growth uniform for `timeMs`; true while rays are growing or the animation loops. */
  tick(timeMs: number): boolean {
    if (!this.animation.animate) return false;
    this.startMs ??= timeMs - (this.resumeTravel / this.speed) * 1000;
    let travel = ((timeMs - this.startMs) / 1000) * this.speed;
    const end = this.drawn.travelEnd;
    if (this.loop) travel %= end + LOOP_PAUSE_S * this.speed;
    this.travel.value = travel;
    return this.loop || travel < end;
  }

  /** The nearest drawn ray (or cone) under the pointer, as far as it has grown. */
  pick(raycaster: Raycaster): RayHover | null {
    const { origin, direction } = raycaster.ray;
    const best = { along: Infinity, at: 0, list: null as SegmentList | null, index: -1 };
    for (const list of [this.drawn.rays, this.drawn.cones]) {
      for (let i = 0; i < list.count; i++) {
        const along = this.pickSegment(list, i, origin, direction);
        if (along < best.along) Object.assign(best, { along, at: this.pickedAt, list, index: i });
      }
    }
    if (!best.list) return null;
    const node = best.list.nodes[best.index];
    const pixel = best.list.pixel[best.index];
    const columns = this.drawn.columns;
    const drawnAs = RAY_COLOR_KEYS[best.list.colorKey[best.index]];
    // A focus draws its pixel as a 1 × 1 screen: the pixel is the trace's own.
    const [x, y] = this.focus ? this.focus.trace.pixel : [pixel % columns, Math.floor(pixel / columns)];
    return { type: node.type, drawnAs, contribution: node.contribution, color: node.color, pixel: [x, y], node, at: best.at, path: this.focus?.paths === true };
  }

  /** A click on a drawn ray, offered to the focus that drew it (the path debugger's vertex choice); true when it took it. */
  click(hover: RayHover): boolean {
    return this.focus?.chooseRay?.(hover.node, hover.at) ?? false;
  }

  dispose(): void {
    this.extras.dispose();
    this.lobe.dispose();
    this.cylinders.dispose();
    this.cones.dispose();
    this.pieceCylinders.dispose();
    this.pieceCones.dispose();
    for (const material of [this.rayMaterial, this.coneMaterial, this.arrowMaterial, this.hiddenMaterial, this.stopMaterial]) material.dispose();
    this.object.clear();
  }

  private writeCylinders(list: SegmentList, dashes: Float32Array): void {
    const buffers = this.cylinders;
    buffers.reserve(list.count);
    const matrix = buffers.mesh.instanceMatrix.array as Float32Array;
    for (let i = 0; i < list.count; i++) writeCylinderMatrix(matrix, i * 16, list, i);
    this.writeAttributes(buffers, list, 1, dashes);
  }

  private writeCones(list: SegmentList): void {
    const buffers = this.cones;
    buffers.reserve(list.count);
    const matrix = buffers.mesh.instanceMatrix.array as Float32Array;
    for (let i = 0; i < list.count; i++) writeConeMatrix(matrix, i * 16, list, i);
    this.writeAttributes(buffers, list, CONE_OPACITY, DASHES_BY_KEY);
  }

  private writeAttributes(buffers: InstanceBuffers, list: SegmentList, opacity: number, dashes: Float32Array): void {
    const { count } = list;
    (buffers.color.array as Float32Array).set(list.color.subarray(0, count * 3));
    const alpha = buffers.alpha.array as Float32Array;
    const growth = buffers.growth.array as Float32Array;
    const dash = buffers.dash?.array as Float32Array | undefined;
    const arrowAt = buffers.arrowAt?.array as Float32Array | undefined;
    const stop = buffers.stop?.array as Float32Array | undefined;
    for (let i = 0; i < count; i++) {
      alpha[i] = list.alpha[i] * opacity;
      growth[i * 2] = list.start[i];
      growth[i * 2 + 1] = list.length[i];
      if (dash && arrowAt && stop) {
        const key = list.colorKey[i];
        if (list.moment[i] >= 0) timeStripe(list.moment[i], dash, i * 2);
        else {
          dash[i * 2] = dashes[key * 2];
          dash[i * 2 + 1] = dashes[key * 2 + 1];
        }
        arrowAt[i] = ARROW_AT_BY_KEY[key];
        stop[i] = STOP_BY_KEY[key];
      }
    }
    buffers.commit(count);
  }

  /** Restarts the growth when what grows changed; only re-times it when just the speed did. */
  private updateAnimation(rays: ScreenRays | null, options: RayViewOptions, selectedPixel: readonly [number, number] | null): void {
    const next: AnimationInputs = { rays, selectedPixel, animate: options.animate, pixelByPixel: options.animatePixelByPixel };
    const previous = this.animation;
    const restart =
      next.rays !== previous.rays ||
      next.animate !== previous.animate ||
      next.pixelByPixel !== previous.pixelByPixel ||
      next.selectedPixel?.[0] !== previous.selectedPixel?.[0] ||
      next.selectedPixel?.[1] !== previous.selectedPixel?.[1];
    const speed = Math.max(options.animationSpeed, 1e-3);
    this.animation = next;
    this.loop = options.loop;
    if (!options.animate) {
      this.travel.value = FULLY_GROWN;
    } else if (restart) {
      this.travel.value = 0;
      this.startMs = null;
      this.resumeTravel = 0;
    } else if (speed !== this.speed && this.startMs !== null) {
      this.startMs = null;
      this.resumeTravel = this.travel.value;
    }
    this.speed = speed;
  }

  /** The debugger's highlighted ray grows once from 0 at the panel's speed (when it was just cast); the others stand. */
  private growFocus(focus: RayFocus, options: RayViewOptions): void {
    // Inputs no screen has: leaving the debugger restarts the usual animation.
    this.animation = { rays: null, selectedPixel: null, animate: focus.grow, pixelByPixel: false };
    this.loop = false;
    this.speed = Math.max(options.animationSpeed, 1e-3);
    this.travel.value = focus.grow ? 0 : FULLY_GROWN;
    this.startMs = null;
    this.resumeTravel = 0;
  }

  /** Where along the last segment pickSegment found the pointer over it: metres from the segment's origin. */
  private pickedAt = 0;

  /** Distance along the pointer ray to segment i when the pointer is over it, else Infinity (and pickedAt set). */
  private pickSegment(list: SegmentList, i: number, origin: Vector3, direction: Vector3): number {
    const grown = Math.min(list.length[i], this.travel.value - list.start[i]);
    if (grown <= 0) return Infinity;
    const o = i * 3;
    const px = list.origin[o];
    const py = list.origin[o + 1];
    const pz = list.origin[o + 2];
    const dx = list.direction[o];
    const dy = list.direction[o + 1];
    const dz = list.direction[o + 2];
    // Closest points of the pointer ray o + t·u (t ≥ 0) and the segment p + s·d (0 ≤ s ≤ grown),
    // both directions unit (Eberly, "Distance between line segments", 2.4).
    const wx = origin.x - px;
    const wy = origin.y - py;
    const wz = origin.z - pz;
    const b = direction.x * dx + direction.y * dy + direction.z * dz;
    const uw = direction.x * wx + direction.y * wy + direction.z * wz;
    const dw = dx * wx + dy * wy + dz * wz;
    const denominator = 1 - b * b;
    let s = denominator > 1e-9 ? (dw - b * uw) / denominator : 0;
    s = Math.min(grown, Math.max(0, s));
    const t = Math.max(0, s * b - uw);
    s = Math.min(grown, Math.max(0, dw + t * b));
    const ex = wx + t * direction.x - s * dx;
    const ey = wy + t * direction.y - s * dy;
    const ez = wz + t * direction.z - s * dz;
    const reach = (list.withCorners ? coneRadiusAt(list, i, s) : list.radius[i]) + PICK_ANGLE * t;
    if (ex * ex + ey * ey + ez * ez > reach * reach) return Infinity;
    this.pickedAt = s;
    return t;
  }
}

/** Whether any of the drawn rays ends stopped (a blocked shadow ray): only then are stop plates drawn. */
function anyStopped(list: SegmentList): boolean {
  for (let i = 0; i < list.count; i++) if (STOP_BY_KEY[list.colorKey[i]] === 1) return true;
  return false;
}

/** A cone's half-width at `s` metres from its apex: the larger half-side of the light, scaled. */
function coneRadiusAt(list: SegmentList, i: number, s: number): number {
  const c = list.corners;
  const k = i * 12;
  const halfWidth = Math.hypot(c[k + 3] - c[k], c[k + 4] - c[k + 1], c[k + 5] - c[k + 2]) / 2;
  const halfDepth = Math.hypot(c[k + 9] - c[k], c[k + 10] - c[k + 1], c[k + 11] - c[k + 2]) / 2;
  return (Math.max(halfWidth, halfDepth) * s) / list.length[i];
}

/**
 * Unit cylinder → ray i: column 0 and 1 an orthonormal basis across the ray scaled by its
 * radius, column 2 the direction scaled by its length, column 3 its origin (column-major,
 * as three.js stores matrices). The helper axis is +Y unless the ray is nearly vertical.
 */
function writeCylinderMatrix(m: Float32Array, at: number, list: SegmentList, i: number): void {
  const o = i * 3;
  const dx = list.direction[o];
  const dy = list.direction[o + 1];
  const dz = list.direction[o + 2];
  const r = list.radius[i];
  const length = list.length[i];
  // x = normalize(helper × d); y = d × x. The square root written out: d is a unit vector, so
  // nothing can overflow, and Math.hypot (varargs, guarded against overflow) was a quarter of
  // a 10k-ray rebuild.
  let xx: number;
  let xy: number;
  let xz: number;
  if (Math.abs(dy) < 0.99) {
    const n = 1 / Math.sqrt(dz * dz + dx * dx);
    xx = dz * n;
    xy = 0;
    xz = -dx * n;
  } else {
    const n = 1 / Math.sqrt(dz * dz + dy * dy);
    xx = 0;
    xy = -dz * n;
    xz = dy * n;
  }
  const yx = dy * xz - dz * xy;
  const yy = dz * xx - dx * xz;
  const yz = dx * xy - dy * xx;
  m[at] = xx * r;
  m[at + 1] = xy * r;
  m[at + 2] = xz * r;
  m[at + 3] = 0;
  m[at + 4] = yx * r;
  m[at + 5] = yy * r;
  m[at + 6] = yz * r;
  m[at + 7] = 0;
  m[at + 8] = dx * length;
  m[at + 9] = dy * length;
  m[at + 10] = dz * length;
  m[at + 11] = 0;
  m[at + 12] = list.origin[o];
  m[at + 13] = list.origin[o + 1];
  m[at + 14] = list.origin[o + 2];
  m[at + 15] = 1;
}

/**
 * Unit pyramid → cone i: apex at the hit point, base (x, y, 1) ↦ centre + x·U + y·V with
 * U, V the light's half-sides from its corners c0..c3 (U = (c1 − c0)/2, V = (c3 − c0)/2).
 */
function writeConeMatrix(m: Float32Array, at: number, list: SegmentList, i: number): void {
  const c = list.corners;
  const k = i * 12;
  const o = i * 3;
  for (let axis = 0; axis < 3; axis++) {
    const apex = list.origin[o + axis];
    const centre = (c[k + axis] + c[k + 3 + axis] + c[k + 6 + axis] + c[k + 9 + axis]) / 4;
    m[at + axis] = (c[k + 3 + axis] - c[k + axis]) / 2;
    m[at + 4 + axis] = (c[k + 9 + axis] - c[k + axis]) / 2;
    m[at + 8 + axis] = centre - apex;
    m[at + 12 + axis] = apex;
  }
  m[at + 3] = 0;
  m[at + 7] = 0;
  m[at + 11] = 0;
  m[at + 15] = 1;
}
