/**
 * The drawn rays: one InstancedMesh of ribbons for every ray (each placed by a unit
 * cylinder's matrix, and turned to the eye by its shader) and one of unit
 * pyramids for the cones (merged area-light rays, wide glossy fans), so drawing 50k rays takes the same two draw
 * calls as drawing 10 (DESIGN.md: "the view draws, it does not decide" — the rules are in
 * ray-visibility.ts). Per instance: a matrix (position, axis, radius, length), a colour,
 * an alpha and the growth animation's (start, length) (ray-shader.ts).
 *
 * Buffers are pooled (instance-buffers.ts): they grow by doubling and never shrink, and an
 * update writes only the instances in use (mesh.count: instance-matrices.ts places them,
 * instance-attributes.ts styles them) and uploads only that range.
 */
import { Group, InstancedMesh, type Raycaster, type Vector3 } from 'three';
import type { RayViewOptions } from '../lab-state/lab-state.ts';
import type { ScreenRays } from '../render/screen-rays.ts';
import { focusedRays, type RayFocus, screenOf } from './ray-focus.ts';
import type { RayHover, RayLayer } from './ray-layer.ts';
import { RayExtras } from './ray-extras.ts';
import { createRayMaterial, FULLY_GROWN, type TravelUniform, type ViewHeightUniform } from './ray-shader.ts';
import { DrawnRays, type RayStyle, type SegmentList, visibleRays } from './ray-visibility.ts';
import { keptRays, type Thinning, thinningOf } from './ray-budget.ts';
import { flattenRays } from './flat-rays.ts';
import { countsEveryRay } from '../tracer/tree-budget.ts';
import { RAY_COLOR_KEYS } from './ray-palette.ts';
import { SamplingLobeMesh } from './sampling-lobe-mesh.ts';
import { FLOATS_PER_CONE, FLOATS_PER_CYLINDER, InstanceBuffers } from './instance-buffers.ts';
import { anyStopped, DASHES_BY_KEY, PATH_DASHES_BY_KEY, writeInstanceAttributes } from './instance-attributes.ts';
import { coneRadiusAt, writeConeMatrix, writeCylinderMatrix } from './instance-matrices.ts';

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

/** The two meshes' names in RayPool.object, where tests and debugging tools look for them. */
export { RAY_CONES_NAME, RAY_CYLINDERS_NAME } from './instance-buffers.ts';

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
  /** The last screen whose every ray was counted: what the note counts while a screen is traced from one sample per pixel. */
  private counted: ScreenRays | null = null;

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
    if (rays && countsEveryRay(rays.traces)) this.counted = rays;
    this.thinned = focus ? null : thinningOf(rays, drawn, kept !== null, selectedPixel !== null, this.counted);
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
    writeInstanceAttributes(buffers, list, 1, dashes);
  }

  private writeCones(list: SegmentList): void {
    const buffers = this.cones;
    buffers.reserve(list.count);
    const matrix = buffers.mesh.instanceMatrix.array as Float32Array;
    for (let i = 0; i < list.count; i++) writeConeMatrix(matrix, i * 16, list, i);
    writeInstanceAttributes(buffers, list, CONE_OPACITY, DASHES_BY_KEY);
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
