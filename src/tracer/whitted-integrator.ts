import { Box3, Vector3 } from 'three';
import type { Material } from '../scene/scene.ts';
import { angleAttenuation, distanceAttenuation } from './attenuation.ts';
import { reflect, refract, schlickReflectance } from './fresnel.ts';
import { Hit } from './hit.ts';
import type { TracerLight } from './lights.ts';
import { Ray } from './ray.ts';
import type { RayNode, RayStats, RayType } from './ray-tree.ts';
import { emptyRayStats } from './ray-tree.ts';
import { hashKey, RandomStream } from './sampler.ts';
import { discPointBuffer, jitteredDiscPoints } from './disc-samples.ts';
import { glossyDirection, perpendicularBasis } from './glossy.ts';
import { LightTermsRecorder, type LightTerms, type ShadingTerms } from './shading-terms.ts';
import { RayCone } from './ray-cone.ts';
import { ShadowPatchPair } from './shadow-patch.ts';
import { phongPower } from './phong-power.ts';
import type { Intersectable } from './intersectable.ts';
import { LightBuffer } from './light-buffer.ts';
import { listOverlapping } from './object-bvh.ts';
import type { PrimaryCandidates } from './primary-candidates.ts';
import { rayMeetsBox } from './ray-box.ts';
import type { TracerScene } from './tracer-scene.ts';

/** Missed rays are drawn this long in the ray tree (spec §3). */
export const MISS_LENGTH = 10;

/** Area lights with at least this many samples get one merged node when all agree (spec §3). */
const MERGE_AREA_SAMPLES = 25;

/** Scratch space for one recursion depth, so tracing allocates nothing per ray. */
class Frame {
  readonly hit = new Hit();
  readonly normal = new Vector3();
  readonly geometricNormal = new Vector3();
  readonly toViewer = new Vector3();
  readonly lightPoint = new Vector3();
  readonly toLight = new Vector3();
  readonly childDirection = new Vector3();
  readonly childOrigin = new Vector3();
  readonly childRay = new Ray();
  readonly childColor = new Vector3();
  readonly shadowRay = new Ray();
  /** Glossy rays: the ideal direction, the basis around it and the jittered disc points. */
  readonly ideal = new Vector3();
  readonly tangent = new Vector3();
  readonly bitangent = new Vector3();
  readonly discPoints = discPointBuffer();
  /** Whether the ray hit the outside of the surface (false: it is inside the object). */
  entering = true;
  /** The box from the hit point to the light being sampled: only objects in it can cast its shadow. */
  readonly shadowReach = new Box3();
  /** An area light's pyramid from the hit point: it culls the candidates in shadowReach further. */
  readonly shadowCone = new RayCone();
  /** The objects overlapping shadowReach (the first `candidateCount` entries), when there are few. */
  readonly candidates: Intersectable[] = [];
  /** -1: too many candidates to list; shadow rays walk the occluder BVHs, limited to shadowReach. */
  candidateCount = 0;
  /** Whether the hit's own shape is listed, and how many other objects are. */
  selfListed = false;
  othersListed = 0;
  /** The distance to the light sample being tested (a field: a number passed to a call is boxed by V8). */
  shadowDistance = 0;
  /** How far the light travelled from the camera to this hit, over all the ray's bounces. */
  pathLength = 0;
  /** Per light: the candidates of the patches of hits at this depth (when rendering). */
  readonly patches: ShadowPatchPair[];

  constructor(lightCount: number) {
    this.patches = Array.from({ length: lightCount }, () => new ShadowPatchPair());
  }
}

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
 * With two patches a light (ShadowPatchPair) the reference scene at 512 × 512 fills one per
 * 3.3 hits, the 256-object grid at 256 × 256 one per 3.2. Twice as wide was 3 % faster on the
 * reference scene and 5 % slower on that grid, where a wider patch lists objects that only
 * block elsewhere in it.
 */
const PATCH_HALF_IN_PIXELS = 1;

const shadowHit = new Hit();

/** Salt so that glossy directions never share random numbers with light sampling. */
const GLOSS_SALT = 0x6c055;

/**
 * Whitted-style recursive ray tracing (Whitted 1980) with the Phong model of spec §2:
 * local light at every hit, plus mirror reflection for opaque specular surfaces and a
 * Schlick-weighted reflection/refraction split for transparent ones; rough materials spread
 * those rays (Cook et al.'s distributed ray tracing, 1984: distribution-effects §2).
 *
 * When a RayNode is passed, the rays are recorded as a tree (spec §3); the arithmetic is
 * the same with or without it, so a pixel's tree has exactly the image's colour.
 */
export class WhittedIntegrator {
  readonly stats: RayStats = emptyRayStats();
  /** What each recorded child adds to its parent per unit of its colour (ks, kr, kt or 1). */
  readonly childWeights = new Map<RayNode, number>();
  /** A recorded hit's colour summed over its channels before clamping: what its children's shares divide (ray-contributions.ts). */
  readonly unclampedSums = new Map<RayNode, number>();
  /** Whether recorded hits also get their shading terms (ray-debugger spec §1); the colours are the same either way. */
  recordTerms = false;
  private readonly frames: Frame[] = [];
  /** The shape that last blocked each light: it is likely to block the next sample too. */
  private readonly lastBlocker: (Intersectable | null)[];
  /** Per point or spot light, its light buffer, made on its first shadow ray that needs it (null until then, and for area lights). */
  private readonly lightBuffers: (LightBuffer | null)[];
  private readonly random = new RandomStream();
  private sampleKey = 0;
  private lightEvaluation = 0;
  private glossEvaluation = 0;
  /** τ of the primary ray being traced: every ray of its tree shares it. */
  private time = 0;
  /** The side of a pixel at distance 1 from the eye in the image being rendered (CameraRays.pixelSpread). */
  pixelSpread = 0;
  /** The objects the primary rays of the tile being rendered can hit (renderTile); null or none listed: they walk the BVH. */
  primaryCandidates: PrimaryCandidates | null = null;

  constructor(private readonly scene: TracerScene) {
    for (let depth = 0; depth <= scene.settings.maxDepth; depth++) this.frames.push(new Frame(scene.lights.length));
    this.lastBlocker = scene.lights.map(() => null);
    this.lightBuffers = scene.lights.map(() => null);
  }

  /** How far a shadow ray may stray from its ideal segment: it covers the rays' ε offsets at both ends (see RayCone). */
  private get shadowMargin(): number {
    return 4 * this.scene.epsilon;
  }

  /** Keys the random numbers of the coming sample by (seed, pixel, sample). */
  startPixelSample(seed: number, x: number, y: number, sample: number): void {
    this.sampleKey = hashKey(seed, x, y, sample);
    this.lightEvaluation = 0;
    this.glossEvaluation = 0;
    this.time = 0;
  }

  /**
   * Keys the random numbers of one lens/time ray of the current pixel sample (when the
   * sample casts more than one) and sets the time its whole tree is traced at.
   */
  startSubSample(seed: number, x: number, y: number, sample: number, subSample: number, time: number): void {
    this.sampleKey = hashKey(seed, x, y, sample, subSample);
    this.lightEvaluation = 0;
    this.glossEvaluation = 0;
    this.time = time;
  }

  /**
   * The colour seen along `ray`, clamped to 0..1 per channel, written into `out`.
   * @param leaving a convex shape the ray leaves outward, which it cannot hit again
   */
  trace(ray: Ray, depth: number, out: Vector3, node: RayNode | null, leaving: Intersectable | null = null): Vector3 {
    const frame = this.frames[depth];
    const hit = frame.hit.reset(Infinity);
    const listed = depth === 0 ? this.primaryCandidates : null;
    if (listed !== null && listed.covers(ray)) {
      // A primary ray of the tile being rendered: its list, in the BVH walk's order (the same hit).
      for (let i = 0; i < listed.count; i++) if (rayMeetsBox(ray, listed.boxes, i * 6, hit.t)) listed.list[i].intersect(ray, hit);
    } else {
      // A reflected or refracted ray starts on the last hit's object: the walk starts at its leaf.
      this.scene.objects.nearest(ray, hit, leaving, null, depth > 0 ? this.frames[depth - 1].hit.shape : null);
    }
    if (!hit.shape) {
      out.fromArray(this.scene.settings.background);
      if (node) recordEnd(node, false, MISS_LENGTH, null, out);
      return out;
    }
    hit.shape.surface(ray, hit);
    frame.pathLength = (depth > 0 ? this.frames[depth - 1].pathLength : 0) + hit.t;
    const terms = this.shade(ray, hit.shape, depth, out, node);
    if (terms) terms.sum = out.toArray();
    if (node) this.unclampedSums.set(node, out.x + out.y + out.z);
    out.clampScalar(0, 1);
    if (node) {
      recordEnd(node, true, hit.t, hit.shape.id, out);
      // N as shade() turned it toward the ray; the deeper frames its children used are others.
      node.normal = frame.normal.toArray();
    }
    if (node && terms) node.terms = terms;
    return out;
  }

  /** Writes the unclamped colour of the hit into `out`; returns its terms when they are recorded. */
  private shade(ray: Ray, shape: Intersectable, depth: number, out: Vector3, node: RayNode | null): ShadingTerms | null {
    const frame = this.frames[depth];
    const { hit, normal: n, geometricNormal: ng, toViewer: v } = frame;
    const material = shape.material;
    // Turn the normals toward the incoming ray; a back-face hit means the ray is inside.
    n.copy(hit.normal);
    ng.copy(hit.geometricNormal);
    const entering = ng.dot(ray.direction) < 0;
    frame.entering = entering;
    if (!entering) {
      n.negate();
      ng.negate();
    }
    v.copy(ray.direction).negate();

    // Ambient: ka·C. The colour is read by index: destructuring an array runs its iterator,
    // which showed as 1 % of a render.
    const color = material.color;
    const cr = color[0], cg = color[1], cb = color[2];
    out.set(cr, cg, cb).multiplyScalar(material.ambient);
    const terms: ShadingTerms | null =
      node && this.recordTerms ? { ambient: out.toArray(), lights: [], reflect: null, refract: null, sum: [0, 0, 0], depthLimited: false } : null;
    // Direct light: Σ la·Lc·C + I·A·S·(diffuse + specular)
    for (let index = 0; index < this.scene.lights.length; index++) {
      const light = this.scene.lights[index];
      const ar = light.ambient * light.color.x * cr;
      const ag = light.ambient * light.color.y * cg;
      const ab = light.ambient * light.color.z * cb;
      out.x += ar;
      out.y += ag;
      out.z += ab;
      const recorder = terms ? new LightTermsRecorder(light.id, [ar, ag, ab]) : null;
      const lightTerms = this.addDirectLight(light, index, frame, material, out, node, recorder);
      if (terms && lightTerms) terms.lights.push(lightTerms);
    }

    if (depth >= this.scene.settings.maxDepth) {
      if (terms) terms.depthLimited = material.transparent || material.specular > 0;
      return terms;
    }
    if (material.transparent) this.addTransmission(ray, frame, material, entering, depth, out, node, terms);
    else if (material.specular > 0) {
      // Opaque specular surface: ks · trace(reflected ray)
      reflect(ray.direction, n, frame.childDirection);
      if (material.roughness > 0) this.traceGlossy('reflect', frame, depth, material.specular, material, out, node, terms);
      else this.traceChild('reflect', frame, depth, material.specular, out, node, terms, leavingShape(frame, frame.childDirection));
    }
    return terms;
  }

  /**
   * Adds one light's diffuse and specular terms (each sample shaded like a spot light).
   * The sample loop is the tracer's hottest code: it works on plain numbers, each operation
   * in the order the Vector3 methods it replaces perform it (l/|l| as l·(1/|l|), as
   * divideScalar does), so the colours stay the same to the bit. The diffuse and the
   * specular parts are summed over the samples apart and then added to `out`, so a hit's
   * terms add up to its colour exactly (shading-terms.ts).
   */
  private addDirectLight(
    light: TracerLight, index: number, frame: Frame, material: Material, out: Vector3, node: RayNode | null, recorder: LightTermsRecorder | null,
  ): LightTerms | null {
    const { hit, normal: n, toViewer: v, lightPoint, toLight: l } = frame;
    const samples = light.sampleCount;
    if (light.type === 'area') this.random.reset(hashKey(this.sampleKey, index, this.lightEvaluation++));
    const sampleNodes: RayNode[] | null = node ? [] : null;
    // The light's colour is divided by n² for an area light's n×n samples (spec §2).
    const scale = light.intensity / samples;
    const color = material.color;
    const cr = color[0], cg = color[1], cb = color[2];
    // The flags the sample loop tests are plain booleans, made so by comparisons (=== true,
    // !== null): V8 does not track that a field holds only booleans, and tests a field's or
    // an object's truthiness against every falsy kind of value (a dozen instructions and
    // five branches) each time. Made so, the reference render took 2.5 % less time.
    const shadows = this.scene.settings.shadows === true;
    const recording = node !== null;
    // Gathered at the first shadow ray: a light wholly behind the surface casts none.
    let gathered = false;
    // Counted here and added to the stats once: a field written per ray costs a store each time.
    let shadowRays = 0;
    const { x: px, y: py, z: pz } = hit.point;
    const { x: nx, y: ny, z: nz } = n;
    const { x: vx, y: vy, z: vz } = v;
    const { x: ngx, y: ngy, z: ngz } = frame.geometricNormal;
    // The hit's shape is left by every ray toward its outer side (see leavingShape).
    const shape = hit.shape!;
    const selfConvex = shape.convex === true && frame.entering === true;
    // A hit inside a convex solid (a ray refracted into a glass ball), with the light apart
    // from it: every ray into the solid's inside meets its far side before the light. So
    // when rendering it is blocked by the solid itself, with no test (a recorded tree tests
    // it, to show its nearest blocker). A plane seen from behind has no inside.
    const insideSelf = !recording && shadows && shape.convex === true && shape.solid === true && frame.entering === false && boxesApart(shape.worldBounds, light.extent, this.shadowMargin) === true;
    const { x: lr, y: lg, z: lb } = light.color;
    // pow(max(R·V, 0), n) can only be 0 when R·V ≤ 0 (and n > 0), and the highlight is 0
    // whenever ks or the light's specular factor is: pow is skipped there.
    const highlights = material.specular > 0 && light.specular > 0;
    const shininess = material.shininess;
    // Σ over the samples of the diffuse and the specular parts, per channel.
    let dr = 0;
    let dg = 0;
    let db = 0;
    let sr = 0;
    let sg = 0;
    let sb = 0;
    // The samples row by row: cell (i, j) of the light's n×n grid.
    const perSide = light.samplesPerSide;
    for (let j = 0; j < perSide; j++) for (let i = 0; i < perSide; i++) {
      light.samplePoint(i, j, this.random, lightPoint);
      let lx = lightPoint.x - px;
      let ly = lightPoint.y - py;
      let lz = lightPoint.z - pz;
      const distance = Math.sqrt(lx * lx + ly * ly + lz * lz);
      if (distance === 0) {
        recorder?.sample(0, 0, 0, 'none');
        continue;
      }
      const inverse = 1 / distance;
      lx *= inverse;
      ly *= inverse;
      lz *= inverse;
      const nDotL = nx * lx + ny * ly + nz * lz;
      // A light behind the surface adds nothing: no ray is cast toward it.
      if (nDotL <= 0) {
        recorder?.sample(lightAttenuation(light, distance, lx, ly, lz), nDotL, 0, 'none');
        continue;
      }
      const attenuation = lightAttenuation(light, distance, lx, ly, lz);
      // Phong: R = 2(N·L)N − L, L mirrored about N; only needed for a highlight (or to show it).
      const twoNDotL = 2 * nDotL;
      const rDotV = highlights || recorder !== null ? (nx * twoNDotL - lx) * vx + (ny * twoNDotL - ly) * vy + (nz * twoNDotL - lz) * vz : 0;
      if (attenuation === 0) {
        recorder?.sample(0, nDotL, rDotV, 'none');
        continue;
      }
      // The unit vector as a Vector3 only for the calls that take one.
      if (recording) l.set(lx, ly, lz);

      let blocker: Intersectable | null = null;
      if (shadows) {
        shadowRays++;
        // The ray starts ε off the surface on the side it leaves toward (offsetOrigin).
        const towardNormal = ngx * lx + ngy * ly + ngz * lz > 0;
        if (insideSelf && towardNormal) blocker = shape;
        else {
          if (!gathered) {
            this.gatherShadowCandidates(frame, light, index, !recording);
            gathered = true;
          }
          frame.shadowDistance = distance;
          // Nothing to test when the list holds only the hit's own shape and the ray leaves it
          // (leavingShape, on plain numbers): most shadow rays on an open floor cost no call.
          const leavesSelf = selfConvex && towardNormal;
          if (frame.candidateCount < 0 || frame.othersListed > 0 || (frame.selfListed === true && !leavesSelf)) {
            l.set(lx, ly, lz);
            blocker = this.firstBlocker(frame, l, index, recording);
          }
        }
      }
      if (blocker !== null) {
        // S = 0: a shadow ray carries black.
        if (sampleNodes !== null) {
          const blocked = newNode('shadow', hit.point, l, shadowHit.t, true, blocker.id, light.id, [0, 0, 0]);
          if (recorder !== null) blocked.parts = { diffuse: [0, 0, 0], specular: [0, 0, 0] };
          sampleNodes.push(blocked);
        }
        recorder?.sample(attenuation, nDotL, rDotV, 'blocked');
        continue;
      }
      // The highlight is not tinted by the object's colour.
      let highlight = 0;
      if (highlights && (!(rDotV <= 0) || shininess === 0)) highlight = phongPower(Math.max(rDotV, 0), shininess) * material.specular * light.specular;
      const diffuse = nDotL * material.diffuse * light.diffuse;
      const k = scale * attenuation;
      const kr = k * lr;
      const kg = k * lg;
      const kb = k * lb;
      const diffuseR = kr * (diffuse * cr);
      const diffuseG = kg * (diffuse * cg);
      const diffuseB = kb * (diffuse * cb);
      dr += diffuseR;
      dg += diffuseG;
      db += diffuseB;
      sr += kr * highlight;
      sg += kg * highlight;
      sb += kb * highlight;
      if (sampleNodes !== null) {
        const reached = newNode('light', hit.point, l, distance, true, null, light.id, [diffuseR + kr * highlight, diffuseG + kg * highlight, diffuseB + kb * highlight]);
        // With Shadows off nothing was tested: the node only records the direction to the light.
        if (!shadows) reached.untested = true;
        if (recorder !== null) reached.parts = { diffuse: [diffuseR, diffuseG, diffuseB], specular: [kr * highlight, kg * highlight, kb * highlight] };
        sampleNodes.push(reached);
      }
      recorder?.sample(attenuation, nDotL, rDotV, 'reached');
    }
    this.stats.shadow += shadowRays;
    out.x += dr;
    out.y += dg;
    out.z += db;
    out.x += sr;
    out.y += sg;
    out.z += sb;
    if (node && sampleNodes) this.recordLightRays(light, frame, sampleNodes, node);
    return recorder ? recorder.finish([dr, dg, db], [sr, sg, sb]) : null;
  }

  /**
   * Every shadow ray from this hit toward this light stays inside the box spanned by the
   * hit point and the light's extent, and for an area light inside the pyramid from the
   * point to its rectangle, so only objects overlapping both can block any of them: found
   * once here (through the object BVHs, cheap shapes first), not once per sample; when
   * rendering, once per patch of neighbouring hits (ShadowPatchPair).
   */
  private gatherShadowCandidates(frame: Frame, light: TracerLight, lightIndex: number, rendering: boolean): void {
    const reach = frame.shadowReach.copy(light.extent).expandByPoint(frame.hit.point);
    // One shadow ray (a point or spot light): listing its candidates would cost a walk of
    // the BVHs on top of the ray's own, which prunes by the ray and not by a box.
    if (light.sampleCount === 1) {
      frame.candidateCount = -1;
      return;
    }
    const margin = this.shadowMargin;
    if (rendering) {
      // Rendering: a patch's list, gathered again only when the hit leaves both cubes.
      const half = PATCH_HALF_IN_PIXELS * this.pixelSpread * frame.pathLength;
      const patch = frame.patches[lightIndex].listFor(frame.hit.point, half, light, this.scene.occluders, margin, MAX_LISTED_CANDIDATES, frame.hit.shape);
      frame.candidateCount = patch.count;
      for (let i = 0; i < patch.count; i++) frame.candidates[i] = patch.list[i];
    } else {
      // A recorded tree lists exactly this hit's candidates, in the BVH's order (below).
      const cone = light.type === 'area' ? frame.shadowCone.toLight(frame.hit.point, light, margin) : null;
      frame.candidateCount = listOverlapping(this.scene.occluders, reach, frame.candidates, MAX_LISTED_CANDIDATES, cone);
    }
    // Shadow-ray coherence (the light buffer's idea, Haines & Greenberg 1986): the object
    // that blocked this light last is the likeliest to block again, so it is tried first.
    // Only when rendering: a recorded tree keeps the BVH's order, so that of two blockers at
    // exactly the same distance it always shows the same one.
    const count = frame.candidateCount;
    if (count < 0) return;
    if (rendering && count > 1) moveToFront(frame.candidates, count, this.lastBlocker[lightIndex]);
    frame.selfListed = false;
    for (let i = 0; i < count; i++) if (frame.candidates[i] === frame.hit.shape) frame.selfListed = true;
    frame.othersListed = count - (frame.selfListed ? 1 : 0);
  }

  /**
   * An object between the hit point and the light at frame.shadowDistance, or null.
   * Rendering only needs to know whether one exists (any-hit: cheap shapes before meshes,
   * the light's last blocker first); a recorded tree shows the nearest one. Both give the
   * same visibility, so the same colour.
   *
   * With a list of candidates (every object that can block any shadow ray from this hit
   * toward this light), only those are tested, and the ray itself is set up only when one
   * of them is not the shape the ray leaves: on an open floor no shadow ray needs one.
   */
  private firstBlocker(frame: Frame, toLight: Vector3, lightIndex: number, nearest: boolean): Intersectable | null {
    const leaving = leavingShape(frame, toLight);
    const { candidates, candidateCount, shadowReach } = frame;
    if (nearest) {
      const ray = this.shadowRay(frame, toLight);
      const hit = shadowHit.reset(ray.far);
      if (candidateCount < 0) this.scene.objects.nearest(ray, hit, leaving, shadowReach);
      else for (let i = 0; i < candidateCount; i++) if (candidates[i] !== leaving) candidates[i].intersect(ray, hit);
      return hit.shape;
    }
    if (candidateCount >= 0) {
      let ray: Ray | null = null;
      for (let i = 0; i < candidateCount; i++) {
        const candidate = candidates[i];
        if (candidate === leaving) continue;
        ray ??= this.shadowRay(frame, toLight);
        if (!candidate.occludes(ray)) continue;
        // Move to front: the next shadow rays of this hit try it first too.
        candidates[i] = candidates[0];
        candidates[0] = candidate;
        this.lastBlocker[lightIndex] = candidate;
        return candidate;
      }
      return null;
    }
    const ray = this.shadowRay(frame, toLight);
    const cached = this.lastBlocker[lightIndex];
    if (cached && cached !== leaving && cached.occludes(ray)) return cached;
    let blocker: Intersectable | null = null;
    const buffer = this.lightBuffer(lightIndex);
    if (buffer !== null) blocker = buffer.firstBlocker(ray, leaving);
    else for (const occluders of this.scene.occluders) if ((blocker = occluders.firstBlocker(ray, leaving, shadowReach, frame.hit.shape))) break;
    if (blocker) this.lastBlocker[lightIndex] = blocker;
    return blocker;
  }

  /** The light buffer of a point or spot light (every shadow ray toward it ends at one point), null for an area light. */
  private lightBuffer(lightIndex: number): LightBuffer | null {
    const light = this.scene.lights[lightIndex];
    if (light.type === 'area') return null;
    // Listed in the occluders' order: cheap shapes before meshes.
    return (this.lightBuffers[lightIndex] ??= new LightBuffer(light.position, this.scene.occluders.flatMap((bvh) => bvh.objectsInOrder()), this.shadowMargin));
  }

  /**
   * The shadow ray from the hit point (moved ε off the surface) along the unit direction
   * `toLight`, reaching to ε short of the light sample at frame.shadowDistance.
   */
  private shadowRay(frame: Frame, toLight: Vector3): Ray {
    const ray = frame.shadowRay.set(offsetOrigin(frame, toLight, this.scene.epsilon), toLight);
    ray.time = this.time;
    ray.far = frame.shadowDistance - this.scene.epsilon;
    return ray;
  }

  /** Transparent surface: kr·trace(reflect) + kt·trace(refract), Schlick's kr (spec §2). */
  private addTransmission(
    ray: Ray, frame: Frame, material: Material, entering: boolean, depth: number, out: Vector3, node: RayNode | null, terms: ShadingTerms | null,
  ): void {
    const n = frame.normal;
    const eta = entering ? 1 / material.refractiveIndex : material.refractiveIndex;
    const refracted = refract(ray.direction, n, eta, frame.childDirection);
    const rough = material.roughness > 0;
    if (!refracted) {
      // Total internal reflection: everything is reflected.
      reflect(ray.direction, n, frame.childDirection);
      if (rough) this.traceGlossy('reflect', frame, depth, 1, material, out, node, terms);
      else this.traceChild('reflect', frame, depth, 1, out, node, terms);
      return;
    }
    // Schlick with the angle on the less dense side: θi entering, θt leaving.
    const cosTheta = entering ? -ray.direction.dot(n) : -frame.childDirection.dot(n);
    const kr = schlickReflectance(cosTheta, material.refractiveIndex);
    if (rough) this.traceGlossy('refract', frame, depth, 1 - kr, material, out, node, terms);
    else this.traceChild('refract', frame, depth, 1 - kr, out, node, terms);
    reflect(ray.direction, n, frame.childDirection);
    if (rough) this.traceGlossy('reflect', frame, depth, kr, material, out, node, terms);
    else this.traceChild('reflect', frame, depth, kr, out, node, terms);
  }

  /**
   * A rough surface (distribution-effects §2): m×m rays spread around the ideal direction
   * in frame.childDirection, each adding weight/m² × its colour. A spread direction on the
   * wrong side of the surface (into it for a reflection, back out for a refraction) is not
   * traced and adds black; a recorded tree keeps it as an absorbed ray of length 0.
   */
  private traceGlossy(
    type: 'reflect' | 'refract', frame: Frame, depth: number, weight: number, material: Material, out: Vector3, node: RayNode | null,
    terms: ShadingTerms | null,
  ): void {
    const { ideal, tangent, bitangent, discPoints, geometricNormal: ng } = frame;
    const m = material.glossySamples;
    ideal.copy(frame.childDirection);
    perpendicularBasis(ideal, tangent, bitangent);
    // Drawn before any child is traced: a child's own light samples restart the stream.
    jitteredDiscPoints(m, this.random.reset(hashKey(this.sampleKey, GLOSS_SALT, this.glossEvaluation++)), discPoints);
    const share = weight / (m * m);
    for (let i = 0; i < m * m; i++) {
      const direction = glossyDirection(ideal, tangent, bitangent, material.roughness, discPoints[i * 2], discPoints[i * 2 + 1], frame.childDirection);
      // ng faces the incoming ray: a reflection must leave on that side, a refraction on the other.
      const side = ng.dot(direction);
      if (type === 'reflect' ? side <= 0 : side >= 0) {
        if (node) {
          const absorbed = newNode(type, frame.hit.point, direction, 0, true, frame.hit.shape?.id ?? null, null, [0, 0, 0]);
          absorbed.glossy = true;
          absorbed.absorbed = true;
          node.children.push(absorbed);
          this.childWeights.set(absorbed, share);
        }
        continue;
      }
      const leaving = type === 'reflect' ? leavingShape(frame, direction) : null;
      const child = this.traceChild(type, frame, depth, share, out, node, terms, leaving);
      if (child) child.glossy = true;
    }
  }

  /** Traces frame.childDirection from the hit point and adds weight × its colour to `out`; returns the recorded child. */
  private traceChild(
    type: 'reflect' | 'refract', frame: Frame, depth: number, weight: number, out: Vector3, node: RayNode | null, terms: ShadingTerms | null,
    leaving: Intersectable | null = null,
  ): RayNode | null {
    this.stats[type]++;
    const origin = offsetOrigin(frame, frame.childDirection, this.scene.epsilon);
    const ray = frame.childRay.set(origin, frame.childDirection);
    ray.time = this.time;
    let child: RayNode | null = null;
    if (node) {
      child = newNode(type, origin, frame.childDirection, 0, false, null, null, [0, 0, 0]);
      node.children.push(child);
      this.childWeights.set(child, weight);
    }
    const color = this.trace(ray, depth + 1, frame.childColor, child, leaving);
    out.addScaledVector(color, weight);
    if (terms) addChildTerm(terms, type, weight, color);
    return child;
  }

  /** Adds a light's sample rays to the tree, merged into one cone when there are many and all agree. */
  private recordLightRays(light: TracerLight, frame: Frame, samples: RayNode[], node: RayNode): void {
    const type = samples[0]?.type;
    const allAgree = samples.length > 0 && samples.every((s) => s.type === type);
    if (light.type !== 'area' || light.sampleCount < MERGE_AREA_SAMPLES || !allAgree) {
      node.children.push(...samples);
      return;
    }
    const toCentre = frame.toLight.subVectors(light.position, frame.hit.point);
    const distance = toCentre.length();
    const color = sumOf(samples.map((s) => s.color));
    const merged = newNode(type === 'light' ? 'area-light' : 'area-shadow', frame.hit.point, toCentre.divideScalar(distance || 1), distance, true, null, light.id, color);
    merged.corners = light.corners().map((c) => c.toArray()) as RayNode['corners'];
    if (this.recordTerms) merged.parts = { diffuse: sumOf(samples.map((s) => s.parts!.diffuse)), specular: sumOf(samples.map((s) => s.parts!.specular)) };
    if (samples[0].untested) merged.untested = true;
    node.children.push(merged);
  }
}

/**
 * A: the distance factor (when on) times the angle factor (spot and area lights), for the unit
 * direction l to the light. Inlined into the sample loop, so its flag is compared with true too.
 */
function lightAttenuation(light: TracerLight, distance: number, lx: number, ly: number, lz: number): number {
  let attenuation = light.distanceAttenuation === true ? distanceAttenuation(distance) : 1;
  if (light.type !== 'point') attenuation *= angleAttenuation(-(light.direction.x * lx + light.direction.y * ly + light.direction.z * lz), light.cosHalfAngle, light.angleExponent);
  return attenuation;
}

/** Moves `first` (when it is among list[0..count-1]) to the front, the others keeping their order. */
function moveToFront(list: Intersectable[], count: number, first: Intersectable | null): void {
  const at = first ? list.indexOf(first) : -1;
  if (at <= 0 || at >= count) return;
  list.copyWithin(1, 0, at);
  list[0] = first!;
}

/** The hit shape, if it is convex and `direction` leaves it from its outside (so cannot meet it again). */
function leavingShape(frame: Frame, direction: Vector3): Intersectable | null {
  const shape = frame.hit.shape;
  return shape && shape.convex && frame.entering && frame.geometricNormal.dot(direction) > 0 ? shape : null;
}

/** Whether the nearest points of two boxes are more than `margin` apart. */
function boxesApart(a: Box3, b: Box3, margin: number): boolean {
  const gx = Math.max(0, a.min.x - b.max.x, b.min.x - a.max.x);
  const gy = Math.max(0, a.min.y - b.max.y, b.min.y - a.max.y);
  const gz = Math.max(0, a.min.z - b.max.z, b.min.z - a.max.z);
  return gx * gx + gy * gy + gz * gz > margin * margin;
}

/** The hit point moved ε off the surface, to the side `direction` leaves toward (no self-hits). */
function offsetOrigin(frame: Frame, direction: Vector3, epsilon: number): Vector3 {
  const ng = frame.geometricNormal;
  const side = ng.dot(direction) >= 0 ? epsilon : -epsilon;
  return frame.childOrigin.copy(frame.hit.point).addScaledVector(ng, side);
}

function newNode(
  type: RayType, origin: Vector3, direction: Vector3, length: number, hit: boolean,
  objectId: string | null, lightId: string | null, color: [number, number, number],
): RayNode {
  return { type, origin: origin.toArray(), direction: direction.toArray(), length, hit, objectId, lightId, color, contribution: 0, children: [] };
}

/** Colours added channel by channel, in order, from 0 (as the sample loop adds them). */
function sumOf(colors: readonly (readonly number[])[]): [number, number, number] {
  return colors.reduce<[number, number, number]>((sum, c) => [sum[0] + c[0], sum[1] + c[1], sum[2] + c[2]], [0, 0, 0]);
}

function recordEnd(node: RayNode, hit: boolean, length: number, objectId: string | null, color: Vector3): void {
  node.hit = hit;
  node.length = length;
  node.objectId = objectId;
  node.color = color.toArray();
}

/**
 * Records what a reflected or refracted child adds. A rough surface's m² spread rays add up
 * to one term: their weights summed, their colour the weighted mean (weight × colour is then
 * what they add together, up to rounding).
 */
function addChildTerm(terms: ShadingTerms, type: 'reflect' | 'refract', weight: number, color: Vector3): void {
  const before = terms[type];
  if (!before) {
    terms[type] = { weight, color: color.toArray() };
    return;
  }
  const total = before.weight + weight;
  terms[type] = { weight: total, color: [0, 1, 2].map((i) => (before.color[i] * before.weight + color.getComponent(i) * weight) / total) as [number, number, number] };
}
