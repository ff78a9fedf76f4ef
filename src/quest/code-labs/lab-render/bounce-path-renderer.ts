import { Vector3 } from 'three';
import { AreaEmitter } from '../../../tracer/area-emitter.ts';
import { Hit } from '../../../tracer/hit.ts';
import { Ray } from '../../../tracer/ray.ts';
import { hashKey, RandomStream } from '../../../tracer/sampler.ts';
import type { TracerScene } from '../../../tracer/tracer-scene.ts';
import type { Vec3 } from '../code-lab-grading.ts';
import { v } from '../lab-vectors.ts';
import { nextTurn, ROWS_PER_TURN } from './lab-renderer.ts';

/** A diffuse bounce's direction around the unit normal `normal`, from the path's own random numbers. */
export type Bounce = (normal: Vec3, random: () => number) => Vec3;

/**
 * A path render made for the cosine-bounce lab: Kajiya's path tracing as the tracer's path
 * mode does it (path-integrator.ts: pbrt-v4's SimplePathIntegrator, §13.3, with light
 * sampling at each diffuse vertex, §13.4, when the scene asks for it; the cosine lab turns it
 * off, cosine-render.ts), on diffuse surfaces only, with every bounce's
 * direction taken from `bounce` and weighted by the albedo alone: Lambert's f·cos θ / pdf
 * is the albedo exactly when the direction comes with density cos θ / π, the lab's contract.
 * A direction that does not come with that density is weighted as if it did, so the picture's
 * mean brightness shows it. Area lights are emitters rays hit (area-emitter.ts); a point or
 * spot light is a point sent its intensity over d² (no cone), reached only by light sampling.
 * `paths` paths per pixel, each through a uniform random point of
 * the pixel; every random number of a path comes from its own stream keyed by (seed, x, y,
 * path), so two renders with different bounces share their other random numbers. Returns
 * the radiance as linear RGB, row by row from the top, as the tracer's images.
 */
export async function renderBouncePaths(scene: TracerScene, bounce: Bounce, width: number, height: number, paths: number, seed: number): Promise<Float32Array> {
  const tracer = new BouncePaths(scene, bounce);
  const image = new Float32Array(width * height * 3);
  const color = new Vector3();
  const stream = new RandomStream();
  const random = () => stream.next();
  for (let y = 0; y < height; y++) {
    if (y > 0 && y % ROWS_PER_TURN === 0) await nextTurn();
    for (let x = 0; x < width; x++) {
      let r = 0;
      let g = 0;
      let b = 0;
      for (let path = 0; path < paths; path++) {
        stream.reset(hashKey(seed, x, y, path));
        tracer.radiance(x + random(), y + random(), width, height, random, color);
        r += color.x;
        g += color.y;
        b += color.z;
      }
      image.set([r / paths, g / paths, b / paths], (y * width + x) * 3);
    }
  }
  return image;
}

class BouncePaths {
  private readonly emitters: (AreaEmitter | null)[];
  private readonly ray = new Ray();
  private readonly shadowRay = new Ray();
  private readonly hit = new Hit();
  private readonly throughput = new Vector3();
  private readonly albedo = new Vector3();
  private readonly normal = new Vector3();
  private readonly geometric = new Vector3();
  private readonly direction = new Vector3();
  private readonly origin = new Vector3();
  private readonly lightPoint = new Vector3();
  private readonly toLight = new Vector3();

  constructor(
    private readonly scene: TracerScene,
    private readonly bounce: Bounce,
  ) {
    this.emitters = scene.lights.map((light) => (light.type === 'area' ? new AreaEmitter(light) : null));
  }

  /** One path's radiance through image point (px, py), into `out`. */
  radiance(px: number, py: number, width: number, height: number, random: () => number, out: Vector3): Vector3 {
    const { scene, ray, hit, throughput, albedo, normal: n, geometric: ng, direction } = this;
    const { settings, epsilon } = scene;
    out.set(0, 0, 0);
    throughput.set(1, 1, 1);
    ray.set(scene.camera.eye, scene.camera.direction(px, py, width, height, direction));
    for (let bounces = 0; ; bounces++) {
      hit.reset(Infinity);
      scene.objects.nearest(ray, hit, null);
      const emitter = this.nearestEmitter(ray, hit.t);
      if (emitter) {
        // With light sampling, an emitter a bounce meets was counted already; a camera ray's is seen directly.
        const counted = settings.lightSampling && bounces > 0;
        if (!counted && ray.direction.dot(emitter.light.direction) < 0) out.add(emitter.radiance.clone().multiply(throughput));
        return out;
      }
      if (hit.shape === null) {
        const [r, g, b] = settings.background;
        return out.add(new Vector3(r, g, b).multiply(throughput));
      }
      const shape = hit.shape;
      shape.surface(ray, hit);
      // maxDepth counts bounces after the first hit; the last bounce's ray adds only what it meets (path-integrator.ts).
      if (bounces > settings.maxDepth) return out;
      n.copy(hit.normal);
      ng.copy(hit.geometricNormal);
      if (ng.dot(ray.direction) > 0) {
        n.negate();
        ng.negate();
      }
      const color = shape.material.color;
      const diffuse = shape.material.diffuse;
      albedo.set(Math.min(1, diffuse * color[0]), Math.min(1, diffuse * color[1]), Math.min(1, diffuse * color[2]));
      this.sampleLights(random, out);
      const next = this.bounce(v(n.x, n.y, n.z), random);
      direction.set(next.x, next.y, next.z);
      // A direction into the surface carries no light: the path ends there, as in the tracer.
      if (ng.dot(direction) <= 0) return out;
      throughput.multiply(albedo);
      ray.set(this.origin.copy(hit.point).addScaledVector(ng, epsilon), direction);
    }
  }

  private nearestEmitter(ray: Ray, tMax: number): AreaEmitter | null {
    let nearest: AreaEmitter | null = null;
    let t = tMax;
    for (const emitter of this.emitters) {
      const distance = emitter ? emitter.intersect(ray, 0, t) : Infinity;
      if (distance < t) {
        t = distance;
        nearest = emitter;
      }
    }
    return nearest;
  }

  /** One point on each light, its light times albedo/π·cos θ over the point's density, when a shadow ray finds the way clear (path-integrator.ts). */
  private sampleLights(random: () => number, out: Vector3): void {
    const { scene, hit, normal: n, geometric: ng, toLight, lightPoint } = this;
    scene.lights.forEach((light, index) => {
      const emitter = this.emitters[index];
      if (emitter && !scene.settings.lightSampling) return;
      if (emitter) emitter.samplePoint(random(), random(), lightPoint);
      else lightPoint.copy(light.position);
      toLight.subVectors(lightPoint, hit.point);
      const distanceSquared = toLight.lengthSq();
      const distance = Math.sqrt(distanceSquared);
      toLight.divideScalar(distance);
      const cosSurface = n.dot(toLight);
      if (cosSurface <= 0 || ng.dot(toLight) <= 0) return;
      // An area light: radiance over the point's density in solid angle, d²/(A·cos θ_light); a point light: intensity over d².
      const cosLight = emitter ? -toLight.dot(light.direction) : 1;
      if (cosLight <= 0) return;
      const radiance = (light.intensity * cosLight * (emitter ? emitter.area : 1)) / distanceSquared;
      if (scene.settings.shadows && !this.unoccluded(toLight, distance)) return;
      out.add(
        light.color
          .clone()
          .multiply(this.albedo)
          .multiply(this.throughput)
          .multiplyScalar((radiance * cosSurface) / Math.PI),
      );
    });
  }

  private unoccluded(toLight: Vector3, distance: number): boolean {
    const { shadowRay, scene } = this;
    shadowRay.set(this.origin.copy(this.hit.point).addScaledVector(this.geometric, scene.epsilon), toLight);
    shadowRay.far = distance - 2 * scene.epsilon;
    return scene.occluders.every((occluders) => occluders.firstBlocker(shadowRay, null, null, this.hit.shape) === null);
  }
}
