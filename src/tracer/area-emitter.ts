import { Vector3 } from 'three';
import { concentricDisc, type TracerLight } from './lights.ts';
import type { Ray } from './ray.ts';

/**
 * An area light as path mode sees it (path-tracing spec §2): a one-sided Lambertian emitter
 * of radiance color·intensity on its lit side (the side its direction points to), black on
 * its back, and a surface that camera rays and bounces hit and that blocks rays like any
 * other. Whitted mode's area lights are only sampled, never hit.
 */
export class AreaEmitter {
  /** Le: the radiance leaving the lit side, the same in every direction. */
  readonly radiance: Vector3;
  readonly area: number;
  private readonly widthSquared: number;
  private readonly depthSquared: number;

  constructor(readonly light: TracerLight) {
    this.radiance = light.color.clone().multiplyScalar(light.intensity);
    this.widthSquared = light.halfWidth.lengthSq();
    this.depthSquared = light.halfDepth.lengthSq();
    const halfWidth = Math.sqrt(this.widthSquared);
    const halfDepth = Math.sqrt(this.depthSquared);
    this.area = light.isDisc ? Math.PI * halfWidth * halfDepth : 4 * halfWidth * halfDepth;
  }

  /**
   * Where `ray` meets the light between `tMin` and `tMax`: its distance, or Infinity. A hit
   * from the lit side is the caller's when `ray.direction` · the light's direction < 0.
   */
  intersect(ray: Ray, tMin: number, tMax: number): number {
    // On plain numbers (every ray of a path meets this test), in the order of the Vector3
    // methods they stand for: docs/performance.md, "Numbers passed to calls".
    const { position: p, direction: n, halfWidth: w, halfDepth: h } = this.light;
    const { origin: o, direction: d } = ray;
    const facing = d.x * n.x + d.y * n.y + d.z * n.z;
    if (facing === 0) return Infinity;
    const t = ((p.x - o.x) * n.x + (p.y - o.y) * n.y + (p.z - o.z) * n.z) / facing;
    if (!(t > tMin && t < tMax)) return Infinity;
    const x = o.x + d.x * t - p.x;
    const y = o.y + d.y * t - p.y;
    const z = o.z + d.z * t - p.z;
    const u = (x * w.x + y * w.y + z * w.z) / this.widthSquared;
    const v = (x * h.x + y * h.y + z * h.z) / this.depthSquared;
    const inside = this.light.isDisc === true ? u * u + v * v <= 1 : Math.abs(u) <= 1 && Math.abs(v) <= 1;
    return inside ? t : Infinity;
  }

  /** A uniform point of the light's surface from u, v in [0, 1): its density per unit area is 1/area. */
  samplePoint(u: number, v: number, out: Vector3): Vector3 {
    let a = 2 * u - 1;
    let b = 2 * v - 1;
    if (this.light.isDisc) [a, b] = concentricDisc(a, b);
    return out.copy(this.light.position).addScaledVector(this.light.halfWidth, a).addScaledVector(this.light.halfDepth, b);
  }
}
