import { Box3, Matrix3, Matrix4, Vector3 } from 'three';
import type { Material } from '../../scene/scene.ts';
import type { Hit } from '../hit.ts';
import type { Ray } from '../ray.ts';

// Scratch vectors at module scope: intersection runs millions of times per render, and
// allocation per test would dominate (three.js does the same in its hot paths).
const localOrigin = new Vector3();
const localDirection = new Vector3();
const corner = new Vector3();

/**
 * A unit shape placed in the world by a transform (spec §1). Rays are moved into object
 * space instead of moving the shape: the direction is not renormalized there, so the ray
 * parameter t means the same world distance in both spaces.
 */
export abstract class Shape {
  /**
   * A ray leaving a convex shape's outer surface can never hit it again, so shadow and
   * mirror rays from it skip it (one test fewer per ray, and no self-shadowing acne).
   */
  abstract readonly convex: boolean;
  readonly worldBounds = new Box3();
  protected readonly worldToObject = new Matrix4();
  /** The linear part of worldToObject: moves directions without renormalizing them. */
  private readonly worldToObjectLinear = new Matrix3();
  private readonly normalToWorld = new Matrix3();

  constructor(
    readonly index: number,
    readonly id: string,
    readonly material: Material,
    readonly objectToWorld: Matrix4,
    objectBounds: Box3,
  ) {
    this.worldToObject.copy(objectToWorld).invert();
    this.worldToObjectLinear.setFromMatrix4(this.worldToObject);
    this.normalToWorld.getNormalMatrix(objectToWorld);
    for (let i = 0; i < 8; i++) {
      corner.set(
        i & 1 ? objectBounds.max.x : objectBounds.min.x,
        i & 2 ? objectBounds.max.y : objectBounds.min.y,
        i & 4 ? objectBounds.max.z : objectBounds.min.z,
      ).applyMatrix4(objectToWorld);
      this.worldBounds.expandByPoint(corner);
    }
    // A little slack so that hits on flat or rotated shapes are not lost to rounding.
    this.worldBounds.expandByScalar(1e-6 * (1 + this.worldBounds.getSize(corner).length()));
  }

  /**
   * If the shape is hit nearer than `hit.t` (and farther than 0), records the hit and
   * returns true.
   */
  intersect(ray: Ray, hit: Hit): boolean {
    if (!rayMeetsBox(ray, this.worldBounds, hit.t)) return false;
    localOrigin.copy(ray.origin).applyMatrix4(this.worldToObject);
    localDirection.copy(ray.direction).applyMatrix3(this.worldToObjectLinear);
    const t = this.intersectLocal(localOrigin, localDirection, hit.t, hit);
    if (t === null) return false;
    hit.t = t;
    hit.shape = this;
    hit.local.copy(localDirection).multiplyScalar(t).add(localOrigin);
    return true;
  }

  /** Fills the hit's world point and outward normals (called once, for the nearest hit). */
  surface(ray: Ray, hit: Hit): void {
    hit.point.copy(ray.direction).multiplyScalar(hit.t).add(ray.origin);
    this.localNormals(hit, hit.geometricNormal, hit.normal);
    hit.geometricNormal.applyMatrix3(this.normalToWorld).normalize();
    hit.normal.applyMatrix3(this.normalToWorld).normalize();
  }

  /**
   * The nearest t in (0, tMax) where the object-space ray o + t·d meets the unit shape,
   * or null. May store extra details (e.g. the triangle) in `hit`.
   */
  protected abstract intersectLocal(o: Vector3, d: Vector3, tMax: number, hit: Hit): number | null;

  /** Outward geometric and shading normals at `hit.local`, in object space (any length). */
  protected abstract localNormals(hit: Hit, geometric: Vector3, shading: Vector3): void;
}

/** Slab test (Kay & Kajiya 1986): does the ray meet the box before `tMax`? */
export function rayMeetsBox(ray: Ray, box: Box3, tMax: number): boolean {
  const { origin: o, inverseDirection: inv } = ray;
  let t0 = (box.min.x - o.x) * inv.x;
  let t1 = (box.max.x - o.x) * inv.x;
  let near = Math.min(t0, t1);
  let far = Math.max(t0, t1);
  t0 = (box.min.y - o.y) * inv.y;
  t1 = (box.max.y - o.y) * inv.y;
  near = Math.max(near, Math.min(t0, t1));
  far = Math.min(far, Math.max(t0, t1));
  t0 = (box.min.z - o.z) * inv.z;
  t1 = (box.max.z - o.z) * inv.z;
  near = Math.max(near, Math.min(t0, t1));
  far = Math.min(far, Math.max(t0, t1));
  // NaN (a ray lying exactly in a slab's plane) compares false, so such rays are kept.
  return !(near > far || far < 0 || near > tMax);
}
