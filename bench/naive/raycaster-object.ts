import { Box3, DoubleSide, type Intersection, Matrix3, Mesh, MeshBasicMaterial, Raycaster } from 'three';
import type { MeshLibrary } from '../../src/scene/mesh-data.ts';
import type { Material, SceneObject } from '../../src/scene/scene.ts';
import { Hit } from '../../src/tracer/hit.ts';
import type { Intersectable } from '../../src/tracer/intersectable.ts';
import type { Ray } from '../../src/tracer/ray.ts';
import { objectToWorld } from '../../src/tracer/tracer-scene.ts';
import { tessellate } from './tessellate.ts';

const scratchHit = new Hit();

/**
 * The baseline most tutorials build: every object a tessellated three.js Mesh, every ray
 * a Raycaster.intersectObject (a bounding-sphere test, then every triangle, no BVH).
 * It plugs into the same integrator, so the shading is identical and only the
 * intersection strategy differs.
 */
export class RaycasterObject implements Intersectable {
  readonly id: string;
  readonly material: Material;
  // Triangles are not convex solids: never skip the object a ray leaves.
  readonly convex = false;
  readonly solid = false;
  readonly worldBounds = new Box3();
  private readonly mesh: Mesh;
  private readonly normalToWorld = new Matrix3();
  private readonly raycaster = new Raycaster();
  private readonly found: Intersection[] = [];
  private lastHit: Intersection | null = null;

  constructor(object: SceneObject, meshes: MeshLibrary) {
    this.id = object.id;
    this.material = object.material;
    this.mesh = new Mesh(tessellate(object, meshes), new MeshBasicMaterial({ side: DoubleSide }));
    this.mesh.matrixAutoUpdate = false;
    this.mesh.matrix.copy(objectToWorld(object));
    this.mesh.matrixWorld.copy(this.mesh.matrix);
    this.normalToWorld.getNormalMatrix(this.mesh.matrixWorld);
    this.worldBounds.setFromObject(this.mesh);
  }

  intersect(ray: Ray, hit: Hit): boolean {
    this.raycaster.set(ray.origin, ray.direction);
    this.raycaster.far = hit.t;
    this.found.length = 0;
    this.mesh.raycast(this.raycaster, this.found);
    let nearest: Intersection | null = null;
    for (const candidate of this.found) {
      if (candidate.distance > 0 && candidate.distance < hit.t && (!nearest || candidate.distance < nearest.distance)) nearest = candidate;
    }
    if (!nearest) return false;
    hit.t = nearest.distance;
    hit.shape = this;
    this.lastHit = nearest;
    return true;
  }

  /** The naive tracer has no any-hit: a nearest-hit search into a scratch record. */
  occludes(ray: Ray): boolean {
    return this.intersect(ray, scratchHit.reset(ray.far));
  }

  surface(ray: Ray, hit: Hit): void {
    hit.point.copy(ray.direction).multiplyScalar(hit.t).add(ray.origin);
    hit.geometricNormal.copy(this.lastHit!.face!.normal).applyMatrix3(this.normalToWorld).normalize();
    hit.normal.copy(hit.geometricNormal);
  }
}
