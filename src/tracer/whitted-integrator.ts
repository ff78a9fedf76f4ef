import type { Vector3 } from 'three';
import type { Material } from '../scene/scene.ts';
import { angleAttenuation, distanceAttenuation } from './attenuation.ts';
import type { Estimator } from './estimator.ts';
import { reflect, refract, relativeIndex, schlickReflectance } from './fresnel.ts';
import { jitteredDiscPoints } from './disc-samples.ts';
import { glossyDirection, perpendicularBasis } from './glossy.ts';
import type { Hit } from './hit.ts';
import type { Intersectable } from './intersectable.ts';
import type { TracerLight } from './lights.ts';
import { phongPower } from './phong-power.ts';
import type { PrimaryCandidates } from './primary-candidates.ts';
import type { Ray } from './ray.ts';
import { rayMeetsBox } from './ray-box.ts';
import type { RayObserver } from './ray-recorder.ts';
import type { RayStats } from './ray-tree.ts';
import { emptyRayStats } from './ray-tree.ts';
import { hashKey, RandomStream } from './sampler.ts';
import { leavingShape, offsetOrigin, ShadingFrame } from './shading-frame.ts';
import { ShadowTester } from './shadow-tester.ts';
import type { TracerScene } from './tracer-scene.ts';
import { GLOSS_STREAM } from './random-streams.ts';

/**
 * Whitted-style recursive ray tracing (Whitted 1980) with the Phong model of spec §2:
 * local light at every hit, plus mirror reflection for opaque specular surfaces and a
 * Schlick-weighted reflection/refraction split for transparent ones; rough materials spread
 * those rays (Cook et al.'s distributed ray tracing, 1984: distribution-effects §2). Its `Li`
 * follows pbrt's WhittedIntegrator (pbrt-v3 §1.3.6); visibility is one call to the
 * ShadowTester, recording one RayObserver argument that rendering passes as null.
 */
export class WhittedIntegrator implements Estimator<RayObserver> {
  readonly stats: RayStats = emptyRayStats();
  /** The objects the primary rays of the tile being rendered can hit (renderTile); null or none listed: they walk the BVH. */
  primaryCandidates: PrimaryCandidates | null = null;
  private readonly frames: ShadingFrame[] = [];
  private readonly shadows: ShadowTester;
  private readonly random = new RandomStream();
  private sampleKey = 0;
  private lightEvaluation = 0;
  private glossEvaluation = 0;
  /** τ of the primary ray being traced: every ray of its tree shares it. */
  private time = 0;

  constructor(private readonly scene: TracerScene) {
    for (let depth = 0; depth <= scene.settings.maxDepth; depth++) this.frames.push(new ShadingFrame(depth));
    this.shadows = new ShadowTester(scene);
  }

  /** The side of a pixel at distance 1 from the eye in the image being rendered: the shadow patches are sized by it. */
  get pixelSpread(): number {
    return this.shadows.pixelSpread;
  }

  set pixelSpread(spread: number) {
    this.shadows.pixelSpread = spread;
  }

  startPixelSample(seed: number, x: number, y: number, sample: number): void {
    this.sampleKey = hashKey(seed, x, y, sample);
    this.lightEvaluation = 0;
    this.glossEvaluation = 0;
    this.time = this.shadows.time = 0;
  }

  startSubSample(seed: number, x: number, y: number, sample: number, subSample: number, time: number): void {
    this.sampleKey = hashKey(seed, x, y, sample, subSample);
    this.lightEvaluation = 0;
    this.glossEvaluation = 0;
    this.time = this.shadows.time = time;
  }

  li(ray: Ray, out: Vector3, recorder: RayObserver | null): Vector3 {
    return this.trace(ray, 0, out, recorder, null);
  }

  /**
   * Li at recursion depth `depth`: the colour seen along `ray`, clamped to 0..1 per channel.
   * @param leaving a convex shape the ray leaves outward, which it cannot hit again
   */
  private trace(ray: Ray, depth: number, out: Vector3, recorder: RayObserver | null, leaving: Intersectable | null): Vector3 {
    const frame = this.frames[depth];
    // Find the nearest hit, or return the background.
    const hit = this.intersect(ray, frame, leaving);
    if (!hit.shape) {
      out.fromArray(this.scene.settings.background);
      recorder?.miss(out);
      return out;
    }
    // The surface at the hit: its point and normals, and the light's path length to it.
    hit.shape.surface(ray, hit);
    frame.pathLength = (depth > 0 ? this.frames[depth - 1].pathLength : 0) + hit.t;
    // The local light and the mirror and glass rays (Whitted's shading model).
    this.shade(ray, hit.shape, frame, out, recorder);
    // Clamp to 0..1 per channel, as the colour the ray carries back (spec §2).
    const sum = recorder !== null ? out.toArray() : null;
    out.clampScalar(0, 1);
    if (recorder !== null) recorder.hit(hit.t, hit.shape.id, frame.normal, sum!, out);
    return out;
  }

  /** The nearest hit along `ray` into frame.hit (none: hit.shape is null). */
  private intersect(ray: Ray, frame: ShadingFrame, leaving: Intersectable | null): Hit {
    const hit = frame.hit.reset(Infinity);
    const depth = frame.depth;
    const listed = depth === 0 ? this.primaryCandidates : null;
    if (listed !== null && listed.covers(ray)) {
      // A primary ray of the tile being rendered: its list, in the BVH walk's order (the same hit).
      for (let i = 0; i < listed.count; i++) if (rayMeetsBox(ray, listed.boxes, i * 6, hit.t)) listed.list[i].intersect(ray, hit);
    } else {
      // A reflected or refracted ray starts on the last hit's object: the walk starts at its leaf.
      this.scene.objects.nearest(ray, hit, leaving, null, depth > 0 ? this.frames[depth - 1].hit.shape : null);
    }
    return hit;
  }

  /** Writes the unclamped colour of frame's hit into `out`. */
  private shade(ray: Ray, shape: Intersectable, frame: ShadingFrame, out: Vector3, recorder: RayObserver | null): void {
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
    // V, toward the viewer.
    v.copy(ray.direction).negate();
    // Ambient: ka·C (the colour read by index: docs/performance.md, "Array reads").
    const color = material.color;
    const cr = color[0],
      cg = color[1],
      cb = color[2];
    out.set(cr, cg, cb).multiplyScalar(material.ambient);
    recorder?.ambient(out);
    // Each light: its ambient la·Lc·C, then I·A·S·(diffuse + specular) over its samples.
    for (let index = 0; index < this.scene.lights.length; index++) {
      const light = this.scene.lights[index];
      const ar = light.ambient * light.color.x * cr;
      const ag = light.ambient * light.color.y * cg;
      const ab = light.ambient * light.color.z * cb;
      out.x += ar;
      out.y += ag;
      out.z += ab;
      recorder?.startLight(light, [ar, ag, ab]);
      this.addDirectLight(light, index, frame, material, out, recorder);
    }
    // At the recursion depth no ray is traced further.
    if (frame.depth >= this.scene.settings.maxDepth) {
      recorder?.depthLimited(material.transparent || material.specular > 0);
      return;
    }
    // Glass: kr·Li(reflected) + kt·Li(refracted).
    if (material.transparent) this.addTransmission(ray, frame, material, entering, out, recorder);
    else if (material.specular > 0) {
      // Mirror: ks·Li(reflected).
      reflect(ray.direction, n, frame.childDirection);
      if (material.roughness > 0) this.traceGlossy('reflect', frame, material.specular, material, out, recorder);
      else this.traceChild('reflect', frame, material.specular, out, recorder, leavingShape(frame, frame.childDirection));
    }
  }

  /**
   * Adds one light's diffuse and specular terms (each sample shaded like a spot light). The
   * sample loop is the tracer's hottest code, written on plain numbers so that the colours
   * are those of the Vector3 methods it stands for, to the bit (l/|l| as l·(1/|l|), as
   * divideScalar does). The diffuse and the specular parts are summed over the samples apart
   * and then added to `out`, so a hit's terms add up to its colour exactly (shading-terms.ts).
   * Its flags are compared with === true: docs/performance.md, "Boolean tests".
   */
  private addDirectLight(light: TracerLight, index: number, frame: ShadingFrame, material: Material, out: Vector3, recorder: RayObserver | null): void {
    const { hit, normal: n, toViewer: v, lightPoint, toLight: l } = frame;
    const samples = light.sampleCount;
    if (light.type === 'area') this.random.reset(hashKey(this.sampleKey, index, this.lightEvaluation++));
    // The light's colour is divided by n² for an area light's n×n samples (spec §2).
    const scale = light.intensity / samples;
    const color = material.color;
    const cr = color[0],
      cg = color[1],
      cb = color[2];
    const shadows = this.scene.settings.shadows === true;
    const recording = recorder !== null;
    if (shadows) this.shadows.startLight(frame, index, recording);
    // Counted here and added to the stats once: docs/performance.md, "Counters".
    let shadowRays = 0;
    const { x: px, y: py, z: pz } = hit.point;
    const { x: nx, y: ny, z: nz } = n;
    const { x: vx, y: vy, z: vz } = v;
    const { x: ngx, y: ngy, z: ngz } = frame.geometricNormal;
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
    for (let j = 0; j < perSide; j++)
      for (let i = 0; i < perSide; i++) {
        // A point on the light, L toward it and its distance.
        light.samplePoint(i, j, this.random, lightPoint);
        let lx = lightPoint.x - px;
        let ly = lightPoint.y - py;
        let lz = lightPoint.z - pz;
        const distance = Math.sqrt(lx * lx + ly * ly + lz * lz);
        if (distance === 0) {
          recorder?.noRay(0, 0, 0);
          continue;
        }
        const inverse = 1 / distance;
        lx *= inverse;
        ly *= inverse;
        lz *= inverse;
        // A light behind the surface adds nothing: no ray is cast toward it.
        const nDotL = nx * lx + ny * ly + nz * lz;
        if (nDotL <= 0) {
          recorder?.noRay(lightAttenuation(light, distance, lx, ly, lz), nDotL, 0);
          continue;
        }
        // A: distance and angle attenuation.
        const attenuation = lightAttenuation(light, distance, lx, ly, lz);
        // Phong: R = 2(N·L)N − L, L mirrored about N; only needed for a highlight (or to show it).
        const twoNDotL = 2 * nDotL;
        const rDotV = highlights || recording ? (nx * twoNDotL - lx) * vx + (ny * twoNDotL - ly) * vy + (nz * twoNDotL - lz) * vz : 0;
        if (attenuation === 0) {
          recorder?.noRay(0, nDotL, rDotV);
          continue;
        }
        // L as a vector, for the shadow tester and the recorder (field by field, and the side
        // N_g·L > 0 computed here: docs/performance.md, "Inlining budget").
        l.x = lx;
        l.y = ly;
        l.z = lz;
        // S: whether the light sample is in view (a shadow ray, when shadows are on).
        let blocker: Intersectable | null = null;
        if (shadows) {
          shadowRays++;
          frame.lightDistance = distance;
          blocker = this.shadows.blocker(frame, ngx * lx + ngy * ly + ngz * lz > 0);
        }
        if (blocker !== null) {
          // S = 0: a shadow ray carries black.
          recorder?.blocked(attenuation, nDotL, rDotV, hit.point, l, this.shadows.blockerDistance, blocker.id, light.id);
          continue;
        }
        // The highlight max(R·V, 0)^n·ks·ls, not tinted by the object's colour.
        let highlight = 0;
        if (highlights && (!(rDotV <= 0) || shininess === 0)) highlight = phongPower(Math.max(rDotV, 0), shininess) * material.specular * light.specular;
        // The diffuse term max(N·L, 0)·kd·ld·C, both scaled by I/n²·A·Lc.
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
        if (recorder !== null) {
          const parts = [kr * highlight, kg * highlight, kb * highlight] as [number, number, number];
          recorder.reached(attenuation, nDotL, rDotV, hit.point, l, distance, light.id, [diffuseR, diffuseG, diffuseB], parts, !shadows);
        }
      }
    this.stats.shadow += shadowRays;
    out.x += dr;
    out.y += dg;
    out.z += db;
    out.x += sr;
    out.y += sg;
    out.z += sb;
    recorder?.finishLight(light, hit.point, [dr, dg, db], [sr, sg, sb]);
  }

  /** Transparent surface: kr·Li(reflected) + kt·Li(refracted), Schlick's kr (spec §2). */
  private addTransmission(ray: Ray, frame: ShadingFrame, material: Material, entering: boolean, out: Vector3, recorder: RayObserver | null): void {
    const n = frame.normal;
    const eta = relativeIndex(entering, material.refractiveIndex);
    const refracted = refract(ray.direction, n, eta, frame.childDirection);
    const rough = material.roughness > 0;
    if (!refracted) {
      // Total internal reflection: everything is reflected.
      reflect(ray.direction, n, frame.childDirection);
      if (rough) this.traceGlossy('reflect', frame, 1, material, out, recorder);
      else this.traceChild('reflect', frame, 1, out, recorder);
      return;
    }
    // Schlick with the angle on the less dense side: θi entering, θt leaving.
    const cosTheta = entering ? -ray.direction.dot(n) : -frame.childDirection.dot(n);
    const kr = schlickReflectance(cosTheta, material.refractiveIndex);
    // kt = 1 − kr: the refracted ray first, then the reflected one.
    if (rough) this.traceGlossy('refract', frame, 1 - kr, material, out, recorder);
    else this.traceChild('refract', frame, 1 - kr, out, recorder);
    reflect(ray.direction, n, frame.childDirection);
    if (rough) this.traceGlossy('reflect', frame, kr, material, out, recorder);
    else this.traceChild('reflect', frame, kr, out, recorder);
  }

  /**
   * A rough surface (distribution-effects §2): m×m rays spread around the ideal direction
   * in frame.childDirection, each adding weight/m² × its colour. A spread direction on the
   * wrong side of the surface (into it for a reflection, back out for a refraction) is not
   * traced and adds black; a recorded tree keeps it as an absorbed ray of length 0.
   */
  private traceGlossy(type: 'reflect' | 'refract', frame: ShadingFrame, weight: number, material: Material, out: Vector3, recorder: RayObserver | null): void {
    const { ideal, tangent, bitangent, discPoints, geometricNormal: ng } = frame;
    const m = material.glossySamples;
    ideal.copy(frame.childDirection);
    perpendicularBasis(ideal, tangent, bitangent);
    // Drawn before any child is traced: a child's own light samples restart the stream.
    jitteredDiscPoints(m, this.random.reset(hashKey(this.sampleKey, GLOSS_STREAM, this.glossEvaluation++)), discPoints);
    const share = weight / (m * m);
    for (let i = 0; i < m * m; i++) {
      const direction = glossyDirection(ideal, tangent, bitangent, material.roughness, discPoints[i * 2], discPoints[i * 2 + 1], frame.childDirection);
      // ng faces the incoming ray: a reflection must leave on that side, a refraction on the other.
      const side = ng.dot(direction);
      if (type === 'reflect' ? side <= 0 : side >= 0) {
        recorder?.absorbed(type, frame.hit.point, direction, frame.hit.shape?.id ?? null, share);
        continue;
      }
      const leaving = type === 'reflect' ? leavingShape(frame, direction) : null;
      const child = this.traceChild(type, frame, share, out, recorder, leaving);
      child?.markGlossy();
    }
  }

  /** Traces frame.childDirection from the hit point and adds weight × its colour to `out`; returns the child's recorder. */
  private traceChild(
    type: 'reflect' | 'refract',
    frame: ShadingFrame,
    weight: number,
    out: Vector3,
    recorder: RayObserver | null,
    leaving: Intersectable | null = null,
  ): RayObserver | null {
    this.stats[type]++;
    const origin = offsetOrigin(frame, frame.childDirection, this.scene.epsilon);
    const ray = frame.childRay.set(origin, frame.childDirection);
    ray.time = this.time;
    const child = recorder !== null ? recorder.child(type, origin, frame.childDirection, weight) : null;
    const color = this.trace(ray, frame.depth + 1, frame.childColor, child, leaving);
    out.addScaledVector(color, weight);
    recorder?.childTerm(type, weight, color);
    return child;
  }
}

/**
 * A: the distance factor (when on) times the angle factor (spot and area lights), for the unit
 * direction l to the light. Inlined into the sample loop, so its flag is compared with true too.
 */
function lightAttenuation(light: TracerLight, distance: number, lx: number, ly: number, lz: number): number {
  let attenuation = light.distanceAttenuation === true ? distanceAttenuation(distance) : 1;
  if (light.type !== 'point')
    attenuation *= angleAttenuation(-(light.direction.x * lx + light.direction.y * ly + light.direction.z * lz), light.cosHalfAngle, light.angleExponent);
  return attenuation;
}
