import { Box3, Matrix3, Matrix4, Vector3 } from 'three';
import type { Material, ShapeKind } from '../../scene/scene.ts';
import type { Hit } from '../hit.ts';
import type { Ray } from '../ray.ts';
import { rayMeetsBox } from '../ray-box.ts';
import { intersectUnitBox, UNIT_BOX_FACE_NORMALS, unitBoxFace } from './box.ts';
import { intersectUnitCylinder, unitCylinderNormal } from './cylinder.ts';
import { intersectMesh, type MeshAccel, meshNormals } from './mesh-accel.ts';
import { meshOccludes } from './mesh-occlusion.ts';
import { intersectPlacedPlane, UNIT_PLANE_NORMAL } from './plane.ts';
import { intersectUnitSphere, unitSphereNormal } from './sphere.ts';
import { FOUND, REACH, unitSpan } from './unit-span.ts';

// Scratch vectors at module scope: intersection runs millions of times per render, and
// allocation per test would dominate (three.js does the same in its hot paths).
const localOrigin = new Vector3();
const localDirection = new Vector3();
const corner = new Vector3();
const span = unitSpan();

const UNIT_BOUNDS = new Box3(new Vector3(-0.5, -0.5, -0.5), new Vector3(0.5, 0.5, 0.5));
const PLANE_BOUNDS = new Box3(new Vector3(-0.5, 0, -0.5), new Vector3(0.5, 0, 0.5));

/**
 * A unit shape (spec §1) placed in the world by a transform. Rays are moved into object
 * space instead of moving the shape: the direction is not renormalized there, so the ray
 * parameter t means the same world distance in both spaces.
 *
 * A shape with a velocity (motion blur) is met at the ray's time: see `localVelocity`.
 *
 * One class for every kind, dispatching on `kind`: the tracer's inner loop then sees one
 * object shape (docs/performance.md, "One class for every shape kind").
 */
export class Shape {
  /**
   * A ray leaving a convex shape's outer surface can never hit it again, so shadow and
   * mirror rays from it skip it (one test fewer per ray, and no self-shadowing acne).
   */
  readonly convex: boolean;
  /** Every kind but the plane encloses a volume. */
  readonly solid: boolean;
  readonly worldBounds = new Box3();
  // The world-to-object affine transform, row by row (m[0..3] is the x row).
  private readonly m = new Float64Array(12);
  // worldBounds as min x, y, z then max x, y, z: the slab test reads it per ray.
  private readonly bounds = new Float64Array(6);
  private readonly normalToWorld = new Matrix3();
  /**
   * A box's six faces' world normals (in unitBoxFace's order) or a plane's one, transformed
   * and normalized once, as surface() did per hit: the same numbers to the bit, without a
   * 3×3 product and a square root per hit. Empty for the curved kinds and meshes.
   */
  private readonly faceNormals: readonly Vector3[];
  /** The object-space offset per unit of time: world-to-object applied to −velocity; null if it stands still. */
  private readonly localVelocity: Vector3 | null;

  constructor(
    readonly index: number,
    readonly id: string,
    readonly material: Material,
    readonly kind: ShapeKind,
    objectToWorld: Matrix4,
    private readonly accel: MeshAccel | null = null,
    velocity: Vector3 | null = null,
  ) {
    this.convex = kind !== 'mesh';
    this.solid = kind !== 'plane';
    const e = new Matrix4().copy(objectToWorld).invert().elements; // column-major
    this.m.set([e[0], e[4], e[8], e[12], e[1], e[5], e[9], e[13], e[2], e[6], e[10], e[14]]);
    this.normalToWorld.getNormalMatrix(objectToWorld);
    const flatFaces = kind === 'box' ? UNIT_BOX_FACE_NORMALS : kind === 'plane' ? [UNIT_PLANE_NORMAL] : [];
    this.faceNormals = flatFaces.map((normal) => new Vector3(...normal).applyMatrix3(this.normalToWorld).normalize());
    const objectBounds = accel ? accel.bounds : kind === 'plane' ? PLANE_BOUNDS : UNIT_BOUNDS;
    for (let i = 0; i < 8; i++) {
      corner
        .set(i & 1 ? objectBounds.max.x : objectBounds.min.x, i & 2 ? objectBounds.max.y : objectBounds.min.y, i & 4 ? objectBounds.max.z : objectBounds.min.z)
        .applyMatrix4(objectToWorld);
      this.worldBounds.expandByPoint(corner);
      // A moving shape's box holds it at every time of the shutter: the box swept along the velocity.
      if (velocity) this.worldBounds.expandByPoint(corner.add(velocity));
    }
    // At time τ the shape is translated by τ·v, so a ray meets it where the ray moved by −τ·v
    // meets it unmoved: in object space, the origin shifts by τ times this (the direction does not).
    this.localVelocity = velocity
      ? new Vector3(
          -(this.m[0] * velocity.x + this.m[1] * velocity.y + this.m[2] * velocity.z),
          -(this.m[4] * velocity.x + this.m[5] * velocity.y + this.m[6] * velocity.z),
          -(this.m[8] * velocity.x + this.m[9] * velocity.y + this.m[10] * velocity.z),
        )
      : null;
    // A little slack so that hits on flat or rotated shapes are not lost to rounding.
    this.worldBounds.expandByScalar(1e-6 * (1 + this.worldBounds.getSize(corner).length()));
    this.bounds.set([...this.worldBounds.min.toArray(), ...this.worldBounds.max.toArray()]);
  }

  /**
   * If the shape is hit nearer than `hit.t` (and farther than 0), records the hit and
   * returns true.
   */
  intersect(ray: Ray, hit: Hit): boolean {
    span[REACH] = hit.t;
    if (!this.meets(ray, hit)) return false;
    const t = span[FOUND];
    hit.t = t;
    hit.shape = this;
    hit.local.copy(localDirection).multiplyScalar(t).add(localOrigin);
    return true;
  }

  /**
   * Any-hit for shadow rays: whether the shape is hit nearer than `ray.far` (and farther
   * than 0), exactly when `intersect` would record a hit, without finding the nearest one.
   */
  occludes(ray: Ray): boolean {
    span[REACH] = ray.far;
    if (this.kind === 'plane') return intersectPlacedPlane(this.m, this.localVelocity, ray, localOrigin, localDirection, span);
    if (!rayMeetsBox(ray, this.bounds, 0, ray.far)) return false;
    this.toLocal(ray);
    switch (this.kind) {
      case 'sphere':
        return intersectUnitSphere(localOrigin, localDirection, span);
      case 'box':
        return intersectUnitBox(localOrigin, localDirection, span);
      case 'cylinder':
        return intersectUnitCylinder(localOrigin, localDirection, span);
      case 'mesh':
        return meshOccludes(this.accel!, localOrigin, localDirection, ray);
    }
  }

  /** The ray in object space, into localOrigin and localDirection (12 multiplies, no renormalizing). */
  private toLocal(ray: Ray): void {
    const m = this.m;
    const { x: ox, y: oy, z: oz } = ray.origin;
    const { x: dx, y: dy, z: dz } = ray.direction;
    localOrigin.set(m[0] * ox + m[1] * oy + m[2] * oz + m[3], m[4] * ox + m[5] * oy + m[6] * oz + m[7], m[8] * ox + m[9] * oy + m[10] * oz + m[11]);
    localDirection.set(m[0] * dx + m[1] * dy + m[2] * dz, m[4] * dx + m[5] * dy + m[6] * dz, m[8] * dx + m[9] * dy + m[10] * dz);
    if (this.localVelocity) localOrigin.addScaledVector(this.localVelocity, ray.time);
  }

  /** Fills the hit's world point and outward unit normals (called once, for the nearest hit). */
  surface(ray: Ray, hit: Hit): void {
    hit.point.copy(ray.direction).multiplyScalar(hit.t).add(ray.origin);
    const geometric = hit.geometricNormal;
    switch (this.kind) {
      case 'sphere':
        unitSphereNormal(hit.local, geometric).applyMatrix3(this.normalToWorld).normalize();
        break;
      case 'box':
        geometric.copy(this.faceNormals[unitBoxFace(hit.local)]);
        break;
      case 'cylinder':
        unitCylinderNormal(hit.local, geometric).applyMatrix3(this.normalToWorld).normalize();
        break;
      case 'plane':
        geometric.copy(this.faceNormals[0]);
        break;
      case 'mesh':
        // Only a mesh's shading normal differs from its geometric one.
        meshNormals(this.accel!, hit, geometric, hit.normal);
        geometric.applyMatrix3(this.normalToWorld).normalize();
        hit.normal.applyMatrix3(this.normalToWorld).normalize();
        return;
    }
    hit.normal.copy(geometric);
  }

  /**
   * Whether the ray meets the shape at a t in (0, span[REACH]): the nearest such t goes to
   * span[FOUND], the ray in object space to localOrigin and localDirection. A plane is tested
   * without its world box (intersectPlacedPlane says why); the other kinds' boxes are tested first.
   */
  private meets(ray: Ray, hit: Hit): boolean {
    if (this.kind === 'plane') return intersectPlacedPlane(this.m, this.localVelocity, ray, localOrigin, localDirection, span);
    if (!rayMeetsBox(ray, this.bounds, 0, span[REACH])) return false;
    this.toLocal(ray);
    switch (this.kind) {
      case 'sphere':
        return intersectUnitSphere(localOrigin, localDirection, span);
      case 'box':
        return intersectUnitBox(localOrigin, localDirection, span);
      case 'cylinder':
        return intersectUnitCylinder(localOrigin, localDirection, span);
      case 'mesh':
        return intersectMesh(this.accel!, localOrigin, localDirection, hit, span);
    }
  }
}
