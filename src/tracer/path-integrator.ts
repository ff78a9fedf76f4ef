import { Vector3 } from 'three';
import { angleAttenuation } from './attenuation.ts';
import { AreaEmitter } from './area-emitter.ts';
import { fresnelDielectric } from './dielectric-fresnel.ts';
import type { Estimator } from './estimator.ts';
import { reflect, refract } from './fresnel.ts';
import { concentricDisc } from './lights.ts';
import { glossyDirection, perpendicularBasis } from './glossy.ts';
import { sampleHemisphere } from './hemisphere-sampling.ts';
import { Hit } from './hit.ts';
import type { Intersectable } from './intersectable.ts';
import type { PathEvent, PathRecorder } from './path-recorder.ts';
import type { PrimaryCandidates } from './primary-candidates.ts';
import { PATH_BOUNCE_STREAM } from './random-streams.ts';
import { Ray } from './ray.ts';
import { rouletteSurvival } from './roulette-survival.ts';
import { emptyRayStats, type RayStats } from './ray-tree.ts';
import { hashIn, hashKey, RandomStream } from './sampler.ts';
import type { TracerScene } from './tracer-scene.ts';

const INV_PI = 1 / Math.PI;

/**
 * A path tracer (Kajiya, "The Rendering Equation", 1986) for the path-tracing spec's
 * `settings.integrator: "path"`: from each camera ray one random path of bounces, whose
 * contributions estimate the rendering equation's integral without bias. Its loop follows
 * pbrt-v4's SimplePathIntegrator (§13.3): at each vertex, light the path sees directly,
 * then light sampling at a diffuse vertex, then one sampled bounce; then Russian roulette,
 * where pbrt-v4's PathIntegrator (§13.4) has it, with Cycles' chance of going on.
 *
 * - Diffuse: Lambert's BRDF albedo/π with albedo min(1, kd·C); `ambient` is not used:
 *   indirect light is computed, not faked.
 * - An opaque material with ks > 0 adds an untinted mirror of reflectance ks (spread by
 *   roughness as in Whitted mode); a bounce picks the mirror with probability ks/(ks + max
 *   albedo), the diffuse lobe otherwise, and divides by that probability.
 * - Glass: a smooth dielectric with the exact Fresnel equations (dielectric-fresnel.ts): a
 *   bounce reflects with probability F and refracts otherwise, which leaves the throughput as
 *   it was (the weight F/F).
 * - Area lights are one-sided emitters (area-emitter.ts) that rays hit; point and spot
 *   lights send radiant intensity color·intensity with 1/d² and can only be reached by light
 *   sampling, so they are always sampled (`lightSampling` switches it for area lights).
 * - `lightSampling` (next-event estimation, pbrt-v4 §13.4): at each diffuse vertex a shadow
 *   ray to a uniform point of each area light; an emitter a diffuse bounce then hits is not
 *   counted again (its light was counted by the sample), so the expected picture is the same.
 * - `maxDepth` counts bounces after the first hit, as Cycles' "max bounces": 0 is direct
 *   light only (what Whitted mode's depth 0 shows), and the last bounce's ray still adds the
 *   emitter or background it meets.
 * - `russianRoulette`: from the second bounce on, a path whose throughput β has fallen below
 *   1 goes on with probability p = √max(β) and carries β/p on (roulette-survival.ts, Cycles' rule).
 *
 * Every random number is drawn from the bounce's own stream, keyed by (seed, pixel, sample,
 * sub-sample) and the bounce, in a fixed order, so `rt trace --paths` re-creates exactly the
 * paths the image averaged (path-recorder.ts).
 */
export class PathIntegrator implements Estimator<PathRecorder> {
  readonly stats: RayStats = emptyRayStats();
  /** Path mode does not use the shadow patches the spread sizes. */
  pixelSpread = 0;
  /** Path mode's primary rays walk the BVH (the candidates list objects only, not emitters). */
  primaryCandidates: PrimaryCandidates | null = null;
  private readonly emitters: AreaEmitter[];
  /** Per light of scene.lights, its emitter (area lights) or null, for light sampling. */
  private readonly emitterOf: (AreaEmitter | null)[];
  private readonly random = new RandomStream();
  /** hashKey(sample's key, PATH_BOUNCE_STREAM), hashed once per path: a bounce's key is hashIn(it, bounce). */
  private bouncesKey = 0;
  private time = 0;
  private readonly ray = new Ray();
  private readonly hit = new Hit();
  private readonly shadowRay = new Ray();
  private readonly throughput = new Vector3();
  private readonly albedo = new Vector3();
  private readonly normal = new Vector3();
  private readonly geometricNormal = new Vector3();
  private readonly direction = new Vector3();
  private readonly origin = new Vector3();
  private readonly tangent = new Vector3();
  private readonly bitangent = new Vector3();
  private readonly ideal = new Vector3();
  private readonly lightPoint = new Vector3();
  private readonly toLight = new Vector3();
  private readonly added = new Vector3();
  /** The distance to the emitter nearestEmitter last found. */
  private emitterDistance = Infinity;
  /** The vertex's shape when it is convex and was hit from outside: a ray leaving toward its outer side cannot meet it again. */
  private leaving: Intersectable | null = null;

  constructor(private readonly scene: TracerScene) {
    this.emitterOf = scene.lights.map((light) => (light.type === 'area' ? new AreaEmitter(light) : null));
    this.emitters = this.emitterOf.filter((emitter) => emitter !== null);
  }

  startPixelSample(seed: number, x: number, y: number, sample: number): void {
    this.bouncesKey = hashKey(hashKey(seed, x, y, sample), PATH_BOUNCE_STREAM);
    this.time = 0;
  }

  startSubSample(seed: number, x: number, y: number, sample: number, subSample: number, time: number): void {
    this.bouncesKey = hashKey(hashKey(seed, x, y, sample, subSample), PATH_BOUNCE_STREAM);
    this.time = time;
  }

  li(cameraRay: Ray, out: Vector3, recorder: PathRecorder | null): Vector3 {
    const { settings, epsilon } = this.scene;
    const { ray, hit, throughput, normal: n, geometricNormal: ng, direction, albedo } = this;
    const random = this.random;
    out.set(0, 0, 0);
    throughput.set(1, 1, 1);
    ray.set(cameraRay.origin, cameraRay.direction);
    ray.time = this.time;
    recorder?.start(ray.origin, ray.direction);
    let bounces = 0;
    /** The last bounce was diffuse with light sampling on: an emitter it meets was counted already. */
    let countedByLightSample = false;
    let skip: Intersectable | null = null;
    let from: Intersectable | null = null;
    for (;;) {
      // The bounce's stream, hashKey(sample's key, PATH_BOUNCE_STREAM, bounces) to the bit.
      random.reset(hashIn(this.bouncesKey, bounces));
      hit.reset(Infinity);
      this.scene.objects.nearest(ray, hit, skip, null, from);
      const emitter = this.nearestEmitter(ray, hit.t, null);
      if (emitter !== null) {
        const lit = ray.direction.dot(emitter.light.direction) < 0;
        if (lit && !countedByLightSample) addProduct(out, throughput, emitter.radiance);
        this.end(recorder, 'emitter', pointAlong(ray, this.emitterDistance, this.origin), null, null, emitter.light.id);
        break;
      }
      if (hit.shape === null) {
        const background = settings.background;
        out.x += throughput.x * background[0];
        out.y += throughput.y * background[1];
        out.z += throughput.z * background[2];
        this.end(recorder, 'escaped', pointAlong(ray, 1, this.origin), null, null, null);
        break;
      }
      const shape = hit.shape;
      shape.surface(ray, hit);
      if (bounces > settings.maxDepth) {
        this.end(recorder, 'max-depth', hit.point, hit.normal, shape.id, null);
        break;
      }
      // Normals toward the incoming ray; a back-face hit means the ray is inside.
      n.copy(hit.normal);
      ng.copy(hit.geometricNormal);
      // The loop's dot products are written out: past V8's inlining budget (docs/performance.md,
      // "Inlining budget") Vector3.dot was called and returned its number boxed, garbage per bounce.
      const d = ray.direction;
      const entering = ng.x * d.x + ng.y * d.y + ng.z * d.z < 0;
      if (!entering) {
        n.negate();
        ng.negate();
      }
      this.leaving = shape.convex && entering ? shape : null;
      const material = shape.material;
      let event: PathEvent;
      let pdf: number | null = null;
      if (material.transparent) {
        // eta = n_t / n_i; refract() takes n_i / n_t.
        const eta = entering ? material.refractiveIndex : 1 / material.refractiveIndex;
        const cosIncident = Math.min(1, -ray.direction.dot(n));
        if (random.next() < fresnelDielectric(cosIncident, eta)) {
          reflect(ray.direction, n, direction);
          event = 'glass-reflect';
        } else {
          refract(ray.direction, n, 1 / eta, direction);
          event = 'glass-refract';
        }
        countedByLightSample = false;
      } else {
        const color = material.color;
        albedo.set(Math.min(1, material.diffuse * color[0]), Math.min(1, material.diffuse * color[1]), Math.min(1, material.diffuse * color[2]));
        const diffuseWeight = Math.max(albedo.x, albedo.y, albedo.z);
        const mirrorWeight = material.specular;
        if (diffuseWeight > 0) this.sampleLights(out, recorder);
        if (diffuseWeight + mirrorWeight <= 0) {
          this.end(recorder, 'absorbed', hit.point, n, shape.id, null);
          break;
        }
        const mirrorChance = mirrorWeight / (diffuseWeight + mirrorWeight);
        if (random.next() < mirrorChance) {
          reflect(ray.direction, n, direction);
          if (material.roughness > 0) this.spread(direction, material.roughness);
          if (ng.dot(direction) <= 0) {
            this.end(recorder, 'absorbed', hit.point, n, shape.id, null);
            break;
          }
          throughput.multiplyScalar(mirrorWeight / mirrorChance);
          event = 'mirror';
          countedByLightSample = false;
        } else {
          pdf = sampleHemisphere(settings.bounceSampling, n, random.next(), random.next(), this.tangent, this.bitangent, direction);
          const cosTheta = n.x * direction.x + n.y * direction.y + n.z * direction.z;
          if (pdf === 0 || ng.x * direction.x + ng.y * direction.y + ng.z * direction.z <= 0) {
            this.end(recorder, 'absorbed', hit.point, n, shape.id, null);
            break;
          }
          // f·cosθ/pdf for Lambert's albedo/π, over the chance of picking the diffuse lobe.
          throughput.multiply(albedo).multiplyScalar((cosTheta * INV_PI) / (pdf * (1 - mirrorChance)));
          event = 'diffuse';
          countedByLightSample = settings.lightSampling;
        }
      }
      recorder?.vertex(event, hit.point, n, shape.id, null, direction, pdf, throughput.toArray());
      bounces++;
      if (event === 'glass-refract') this.stats.refract++;
      else this.stats.reflect++;
      if (settings.russianRoulette && bounces >= 2) {
        const survival = rouletteSurvival(Math.max(throughput.x, throughput.y, throughput.z));
        if (survival < 1) {
          if (random.next() >= survival) {
            this.end(recorder, 'roulette-stop', hit.point, n, shape.id, null);
            break;
          }
          throughput.divideScalar(survival);
        }
      }
      // The next ray starts ε off the surface, on the side it leaves toward.
      const leaving = ng.x * direction.x + ng.y * direction.y + ng.z * direction.z;
      const side = leaving >= 0 ? epsilon : -epsilon;
      ray.set(this.origin.copy(hit.point).addScaledVector(ng, side), direction);
      skip = shape.convex && entering && leaving > 0 ? shape : null;
      from = shape;
    }
    recorder?.end(out);
    return out;
  }

  /** The area light `ray` meets first, nearer than `tMax` (and not `except`), or null. */
  private nearestEmitter(ray: Ray, tMax: number, except: AreaEmitter | null): AreaEmitter | null {
    let nearest: AreaEmitter | null = null;
    let t = tMax;
    for (const emitter of this.emitters) {
      if (emitter === except) continue;
      const distance = emitter.intersect(ray, 0, t);
      if (distance < t) {
        t = distance;
        nearest = emitter;
      }
    }
    this.emitterDistance = t;
    return nearest;
  }

  /**
   * Light sampling at the diffuse vertex in this.hit (pbrt-v4 §13.4): for each light, one
   * point on it; what it sends toward the vertex, times albedo/π·cosθ over the point's
   * density, is added to the path's colour `out` when a shadow ray finds the way clear (or shadows are off).
   */
  private sampleLights(out: Vector3, recorder: PathRecorder | null): void {
    const { settings, lights } = this.scene;
    const { random, hit, normal: n, geometricNormal: ng, toLight, lightPoint, added, throughput, albedo } = this;
    for (let index = 0; index < lights.length; index++) {
      const light = lights[index];
      const emitter = this.emitterOf[index];
      let radiance: number;
      if (emitter !== null) {
        if (!settings.lightSampling) continue;
        emitter.samplePoint(random.next(), random.next(), lightPoint);
      } else lightPoint.copy(light.position);
      toLight.subVectors(lightPoint, hit.point);
      const distanceSquared = toLight.lengthSq();
      const distance = Math.sqrt(distanceSquared);
      toLight.divideScalar(distance);
      const cosSurface = n.x * toLight.x + n.y * toLight.y + n.z * toLight.z;
      if (cosSurface <= 0 || ng.x * toLight.x + ng.y * toLight.y + ng.z * toLight.z <= 0) continue;
      if (emitter !== null) {
        // Radiance Le over the point's density in solid angle, d²/(A·cosθ_light).
        const facing = light.direction;
        const cosLight = -(toLight.x * facing.x + toLight.y * facing.y + toLight.z * facing.z);
        if (cosLight <= 0) continue;
        radiance = (light.intensity * cosLight * emitter.area) / distanceSquared;
      } else {
        // Radiant intensity I with 1/d²; a spot's cone and cos^p fall-off as in Whitted mode.
        const cone = light.type === 'spot' ? angleAttenuation(-toLight.dot(light.direction), light.cosHalfAngle, light.angleExponent) : 1;
        radiance = (light.intensity * cone) / distanceSquared;
      }
      if (radiance <= 0) continue;
      added
        .copy(light.color)
        .multiply(albedo)
        .multiply(throughput)
        .multiplyScalar(radiance * cosSurface * INV_PI);
      const visible = !settings.shadows || this.unoccluded(toLight, distance, emitter);
      if (visible) out.add(added);
      recorder?.lightSample(light.id, lightPoint, visible, visible ? added.toArray() : [0, 0, 0]);
    }
  }

  /** Whether nothing (object or other area light) lies between this.hit and the light `distance` away along `toLight`. */
  private unoccluded(toLight: Vector3, distance: number, emitter: AreaEmitter | null): boolean {
    const epsilon = this.scene.epsilon;
    const shadowRay = this.shadowRay;
    shadowRay.set(this.origin.copy(this.hit.point).addScaledVector(this.geometricNormal, epsilon), toLight);
    shadowRay.time = this.time;
    this.stats.shadow++;
    const far = distance - 2 * epsilon;
    // Any blocker will do, not the nearest (pbrt-v4's Unoccluded, §7.1 and §13.4); the
    // convex shapes first, as Whitted mode's shadow rays try them. The vertex's own shape is
    // skipped when the ray leaves its outside (sampleLights only casts toward that side).
    shadowRay.far = far;
    for (const occluders of this.scene.occluders) if (occluders.firstBlocker(shadowRay, this.leaving, null, this.hit.shape) !== null) return false;
    return this.nearestEmitter(shadowRay, far, emitter) === null;
  }

  /** Spreads the mirror direction by roughness ρ around itself, as Whitted mode's glossy rays (distribution-effects §2). */
  private spread(direction: Vector3, roughness: number): void {
    this.ideal.copy(direction);
    perpendicularBasis(this.ideal, this.tangent, this.bitangent);
    const [a, b] = concentricDisc(2 * this.random.next() - 1, 2 * this.random.next() - 1);
    glossyDirection(this.ideal, this.tangent, this.bitangent, roughness, a, b, direction);
  }

  private end(recorder: PathRecorder | null, event: PathEvent, point: Vector3, normal: Vector3 | null, objectId: string | null, lightId: string | null): void {
    recorder?.vertex(event, point, normal, objectId, lightId, null, null, this.throughput.toArray());
  }
}

/** out += a × b, per channel. */
function addProduct(out: Vector3, a: Vector3, b: Vector3): void {
  out.x += a.x * b.x;
  out.y += a.y * b.y;
  out.z += a.z * b.z;
}

/** The point `t` along `ray`, into `out`. */
function pointAlong(ray: Ray, t: number, out: Vector3): Vector3 {
  return out.copy(ray.origin).addScaledVector(ray.direction, t);
}
