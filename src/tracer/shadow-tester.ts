import { Box3 } from 'three';
import { Hit } from './hit.ts';
import type { Intersectable } from './intersectable.ts';
import { LightBuffer } from './light-buffer.ts';
import { listOverlapping } from './object-bvh.ts';
import { Ray } from './ray.ts';
import { RayCone } from './ray-cone.ts';
import { leavingShape, offsetOrigin, type ShadingFrame } from './shading-frame.ts';
import { ShadowPatchPair } from './shadow-patch.ts';
import type { TracerScene } from './tracer-scene.ts';

/**
 * Up to this many shadow candidates per hit and light are tried in a list by every shadow
 * ray; with more (a crowded scene), each shadow ray walks the object BVHs instead.
 */
const MAX_LISTED_CANDIDATES = 8;

/**
 * A shadow patch's half-side, in pixel footprints at the hit that starts it: a cube about 2
 * pixels wide, so that the next pixels' hits fall in it whatever the image's size or the
 * scene's scale. A hit's footprint is the camera's pixel spread times the light's path from
 * the eye: exact for a surface facing the camera and after flat mirrors, a guess after a
 * curved one (ray cones: Amanatides 1984; Akenine-Möller et al. 2019). A guess costs time,
 * never correctness: every patch lists every object that can block any of its shadow rays.
 * Why 1 and not 2: docs/performance.md, "Shadow patch size".
 */
const PATCH_HALF_IN_PIXELS = 1;

/** What a shadow ray needs, decided per hit and light and side of the surface (ShadowTester). */
type Verdict = typeof UNKNOWN | typeof CLEAR | typeof TEST | typeof BLOCKED_BY_SELF;
/** Not known until the candidates are gathered. */
const UNKNOWN = 0;
/** Nothing listed can block it: it reaches the light, with no test. */
const CLEAR = 1;
/** It is tested against the candidates (or the BVHs). */
const TEST = 2;
/** It goes into the convex solid the hit is inside of, which blocks it. */
const BLOCKED_BY_SELF = 3;

/**
 * Answers one question for the shading code: what blocks the shadow ray from a hit to a
 * light sample (pbrt-v4's `Unoccluded`, which says it in one line). The answer is exactly
 * what testing the ray against every object would give; behind the one call sit the
 * accelerators that make the answer cheap:
 *
 * 1. no test where the hit is inside a convex solid the light is outside of (it blocks);
 * 2. per hit and light, only the objects that can block any of its rays are listed (the box
 *    and, for an area light, the pyramid from the point to the light), when they are few;
 * 3. when rendering, that list is kept for a patch of neighbouring hits (ShadowPatchPair);
 * 4. no ray at all when the list holds only the surface the rays leave;
 * 5. the object that blocked the light last is tried first (Haines & Greenberg 1986);
 * 6. a point or spot light's rays test the objects of one cell of its light buffer (LightBuffer);
 * 7. when rendering, any blocker will do (any-hit); a recorded tree gets the nearest one,
 *    in the BVH's order, so that of two at the same distance it always shows the same.
 *
 * Shadow rays are tested one hit and one light at a time: `startLight`, then `blocker` per ray.
 */
export class ShadowTester {
  /** τ of the ray tree being traced: its shadow rays see the moving objects at that time. */
  time = 0;
  /** The side of a pixel at distance 1 from the eye in the image being rendered (CameraRays.pixelSpread): sizes the patches. */
  pixelSpread = 0;
  /** How far a shadow ray may stray from its ideal segment: it covers the rays' ε offsets at both ends (see RayCone). */
  private readonly margin: number;
  private lightIndex = 0;
  /** A recorded tree: the nearest blocker, not any. */
  private nearest = false;
  /**
   * What a shadow ray of this hit and light needs (a Verdict), for rays toward the side the
   * geometric normal faces and for rays toward the other side: decided per hit and light, so
   * that most rays cost one comparison here.
   */
  private outward: Verdict = UNKNOWN;
  private inward: Verdict = UNKNOWN;
  /** The hit is on the outside of a convex shape: a ray toward its outer side cannot meet it again (leavingShape). */
  private selfConvex = false;
  /** The box from the hit point to the light: only objects in it can cast its shadow. */
  private readonly reach = new Box3();
  /** An area light's pyramid from the hit point: it culls the candidates in `reach` further. */
  private readonly cone = new RayCone();
  /** The objects that can block this hit's rays toward this light (the first `candidateCount`). */
  private readonly candidates: Intersectable[] = [];
  /** -1: too many to list; the rays walk the occluder BVHs, limited to `reach`. */
  private candidateCount = 0;
  private readonly ray = new Ray();
  private readonly hit = new Hit();
  /** The shape that last blocked each light: it is likely to block the next sample too. */
  private readonly lastBlocker: (Intersectable | null)[];
  /** Per point or spot light, its light buffer, made at its first ray that needs it (null until then, and for area lights). */
  private readonly lightBuffers: (LightBuffer | null)[];
  /** Per recursion depth and light: the candidates of the patches of hits at that depth (when rendering). */
  private readonly patches: ShadowPatchPair[][];

  constructor(private readonly scene: TracerScene) {
    this.margin = 4 * scene.epsilon;
    this.lastBlocker = scene.lights.map(() => null);
    this.lightBuffers = scene.lights.map(() => null);
    this.patches = Array.from({ length: scene.settings.maxDepth + 1 }, () => scene.lights.map(() => new ShadowPatchPair()));
  }

  /** The distance to the blocker the last `blocker` call found when asked for the nearest one. */
  get blockerDistance(): number {
    return this.hit.t;
  }

  /** Starts the shadow rays from frame's hit toward light `lightIndex`; `nearest`: a recorded tree's (see 7 above). */
  startLight(frame: ShadingFrame, lightIndex: number, nearest: boolean): void {
    const shape = frame.hit.shape!;
    this.lightIndex = lightIndex;
    this.nearest = nearest;
    this.selfConvex = shape.convex === true && frame.entering === true;
    // A hit inside a convex solid (a ray refracted into a glass ball), with the light apart
    // from it: every ray into the solid's inside meets its far side before the light. A
    // recorded tree tests it, to show its nearest blocker. A plane seen from behind has no inside.
    const insideSelf =
      nearest === false &&
      shape.convex === true &&
      shape.solid === true &&
      frame.entering === false &&
      boxesApart(shape.worldBounds, this.scene.lights[lightIndex].extent, this.margin) === true;
    // The candidates are gathered at the first ray that needs them: a light wholly behind the surface needs none.
    this.outward = insideSelf ? BLOCKED_BY_SELF : UNKNOWN;
    this.inward = UNKNOWN;
  }

  /**
   * What blocks the shadow ray from frame's hit along the unit direction frame.toLight to the
   * light sample at frame.lightDistance, or null when the ray reaches it. `outward`: whether
   * the ray leaves toward the side the (turned) geometric normal faces, N_g·L > 0. Kept this
   * small so that the sample loop inlines it: docs/performance.md, "Inlining budget".
   */
  blocker(frame: ShadingFrame, outward: boolean): Intersectable | null {
    return (outward ? this.outward : this.inward) === CLEAR ? null : this.test(frame, outward);
  }

  /** The blocker of a ray whose verdict is not CLEAR (blocker's arguments). */
  private test(frame: ShadingFrame, outward: boolean): Intersectable | null {
    let verdict = outward ? this.outward : this.inward;
    if (verdict === BLOCKED_BY_SELF) return frame.hit.shape;
    if (verdict === UNKNOWN) {
      this.gather(frame);
      verdict = outward ? this.outward : this.inward;
      if (verdict === CLEAR) return null;
    }
    return this.firstBlocker(frame);
  }

  /**
   * Every shadow ray from this hit toward this light stays inside the box spanned by the
   * hit point and the light's extent, and for an area light inside the pyramid from the
   * point to its rectangle, so only objects overlapping both can block any of them: found
   * once here (through the object BVHs, cheap shapes first), not once per sample; when
   * rendering, once per patch of neighbouring hits (ShadowPatchPair).
   */
  private gather(frame: ShadingFrame): void {
    const light = this.scene.lights[this.lightIndex];
    const reach = this.reach.copy(light.extent).expandByPoint(frame.hit.point);
    const rendering = !this.nearest;
    // One shadow ray (a point or spot light): listing its candidates would cost a walk of
    // the BVHs on top of the ray's own, which prunes by the ray and not by a box.
    if (light.sampleCount === 1) this.candidateCount = -1;
    else if (rendering) {
      // Rendering: a patch's list, gathered again only when the hit leaves both cubes.
      const half = PATCH_HALF_IN_PIXELS * this.pixelSpread * frame.pathLength;
      const patch = this.patches[frame.depth][this.lightIndex].listFor(
        frame.hit.point,
        half,
        light,
        this.scene.occluders,
        this.margin,
        MAX_LISTED_CANDIDATES,
        frame.hit.shape,
      );
      this.candidateCount = patch.count;
      for (let i = 0; i < patch.count; i++) this.candidates[i] = patch.list[i];
    } else {
      // A recorded tree lists exactly this hit's candidates, in the BVH's order (below).
      const cone = light.type === 'area' ? this.cone.toLight(frame.hit.point, light, this.margin) : null;
      this.candidateCount = listOverlapping(this.scene.occluders, reach, this.candidates, MAX_LISTED_CANDIDATES, cone);
    }
    // The object that blocked this light last is the likeliest to block again, so it is tried
    // first; only when rendering (7 above).
    const count = this.candidateCount;
    if (rendering && count > 1) moveToFront(this.candidates, count, this.lastBlocker[this.lightIndex]);
    let selfListed = false;
    for (let i = 0; i < count; i++) if (this.candidates[i] === frame.hit.shape) selfListed = true;
    const othersListed = count - (selfListed ? 1 : 0);
    // Nothing to test when the list holds only the hit's own shape and the ray leaves it
    // (a ray toward the outer side of a convex shape): most shadow rays on an open floor.
    const mustTest = count < 0 || othersListed > 0;
    if (this.outward === UNKNOWN) this.outward = mustTest || (selfListed && !this.selfConvex) ? TEST : CLEAR;
    this.inward = mustTest || selfListed ? TEST : CLEAR;
  }

  /**
   * The listed or walked object between the hit point and the light sample, or null. Rendering
   * only needs to know whether one exists (any-hit: cheap shapes before meshes, the light's
   * last blocker first); a recorded tree shows the nearest one. Both give the same visibility.
   * With a list, the ray itself is set up only when one of its objects is not the shape the
   * ray leaves: on an open floor no shadow ray needs one.
   */
  private firstBlocker(frame: ShadingFrame): Intersectable | null {
    const lightIndex = this.lightIndex;
    const leaving = leavingShape(frame, frame.toLight);
    const { candidates, candidateCount, reach } = this;
    if (this.nearest) {
      const ray = this.shadowRay(frame);
      const hit = this.hit.reset(ray.far);
      if (candidateCount < 0) this.scene.objects.nearest(ray, hit, leaving, reach);
      else for (let i = 0; i < candidateCount; i++) if (candidates[i] !== leaving) candidates[i].intersect(ray, hit);
      return hit.shape;
    }
    if (candidateCount >= 0) {
      let ray: Ray | null = null;
      for (let i = 0; i < candidateCount; i++) {
        const candidate = candidates[i];
        if (candidate === leaving) continue;
        ray ??= this.shadowRay(frame);
        if (!candidate.occludes(ray)) continue;
        // Move to front: the next shadow rays of this hit try it first too.
        candidates[i] = candidates[0];
        candidates[0] = candidate;
        this.lastBlocker[lightIndex] = candidate;
        return candidate;
      }
      return null;
    }
    const ray = this.shadowRay(frame);
    const cached = this.lastBlocker[lightIndex];
    if (cached && cached !== leaving && cached.occludes(ray)) return cached;
    let blocker: Intersectable | null = null;
    const buffer = this.lightBuffer(lightIndex);
    if (buffer !== null) blocker = buffer.firstBlocker(ray, leaving);
    else for (const occluders of this.scene.occluders) if ((blocker = occluders.firstBlocker(ray, leaving, reach, frame.hit.shape))) break;
    if (blocker) this.lastBlocker[lightIndex] = blocker;
    return blocker;
  }

  /** The light buffer of a point or spot light (every shadow ray toward it ends at one point), null for an area light. */
  private lightBuffer(lightIndex: number): LightBuffer | null {
    const light = this.scene.lights[lightIndex];
    if (light.type === 'area') return null;
    // Listed in the occluders' order: cheap shapes before meshes.
    return (this.lightBuffers[lightIndex] ??= new LightBuffer(
      light.position,
      this.scene.occluders.flatMap((bvh) => bvh.objectsInOrder()),
      this.margin,
    ));
  }

  /**
   * The shadow ray from the hit point (moved ε off the surface) along frame.toLight,
   * reaching to ε short of the light sample at frame.lightDistance.
   */
  private shadowRay(frame: ShadingFrame): Ray {
    const epsilon = this.scene.epsilon;
    const ray = this.ray.set(offsetOrigin(frame, frame.toLight, epsilon), frame.toLight);
    ray.time = this.time;
    ray.far = frame.lightDistance - epsilon;
    return ray;
  }
}

/** Moves `first` (when it is among list[0..count-1]) to the front, the others keeping their order. */
function moveToFront(list: Intersectable[], count: number, first: Intersectable | null): void {
  const at = first ? list.indexOf(first) : -1;
  if (at <= 0 || at >= count) return;
  list.copyWithin(1, 0, at);
  list[0] = first!;
}

/** Whether the nearest points of two boxes are more than `margin` apart. */
function boxesApart(a: Box3, b: Box3, margin: number): boolean {
  const gx = Math.max(0, a.min.x - b.max.x, b.min.x - a.max.x);
  const gy = Math.max(0, a.min.y - b.max.y, b.min.y - a.max.y);
  const gz = Math.max(0, a.min.z - b.max.z, b.min.z - a.max.z);
  return gx * gx + gy * gy + gz * gz > margin * margin;
}
