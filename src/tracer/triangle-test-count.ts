import { Box3, Matrix3, Ray as ThreeRay, Vector3 } from 'three';
import type { MeshLibrary } from '../scene/mesh-data.ts';
import { type BvhNode, bvhTree } from './bvh-tree.ts';
import { Hit } from './hit.ts';
import { Ray } from './ray.ts';
import { type MeshAccel, meshAccel } from './shapes/mesh-accel.ts';
import { objectToWorld, type TracerScene } from './tracer-scene.ts';

/** What one ray cost against one model: boxes and triangles tested, and the nearest hit. */
export interface MeshTests {
  /** BVH boxes tested (the root's included). */
  boxes: number;
  /** Ray–triangle tests done. */
  triangles: number;
  /** The model's triangle count: what testing without a BVH (brute force) costs. */
  bruteForce: number;
  /** The nearest hit's t along the given direction, or Infinity. */
  t: number;
  /** Every box tested, in the walk's order: entered (the ray meets it) or missed (its subtree skipped). */
  visits: BoxVisit[];
}

/** One BVH box test of a ray's walk. */
export interface BoxVisit {
  node: BvhNode;
  /** True when the ray met the box and the walk went inside; false when the test failed. */
  entered: boolean;
}

/** What one ray cost against one object of a scene. */
export interface ObjectTests {
  id: string;
  /** Whether the ray met the object's world bounding box (the tracer's slab test) in time to matter. */
  boundsHit: boolean;
  /** Mesh objects: the cost inside the BVH (zero tests when the bounds were missed); null for analytic shapes. */
  mesh: MeshTests | null;
}

/** What one ray cost against a whole scene, object by object, in the order the tracer tests them. */
export interface RayTests {
  objects: ObjectTests[];
  /** Bounding-box tests of whole objects: one per object. */
  boundsTests: number;
  /** Ray–triangle tests over all mesh objects. */
  triangles: number;
  /** All triangles of all mesh objects: the tests without any boxes. */
  bruteForce: number;
  /** The id of the object the ray hits first, or null. */
  hitId: string | null;
}

const unitRay = new ThreeRay();
const point = new Vector3();
const a = new Vector3();
const b = new Vector3();
const c = new Vector3();

/**
 * Counts the tests the tracer's mesh intersection (`meshNearest`, which walks the model's
 * BVH as three-mesh-bvh's `raycastFirst` does) makes for the object-space ray o + t·d, t in
 * (0, tMax). It walks the same tree in the same way: the near child first (by the split
 * axis and the ray's direction), and the far child skipped when the near one's hit lies on
 * the near side of it. Every box and triangle test it makes is counted.
 */
export function countMeshTests(accel: MeshAccel, o: Vector3, d: Vector3, tMax: number): MeshTests {
  return walkMesh(accel, o, d, tMax, (counter, root) => (counter.meetsBox(root) ? counter.nearest(root) : null));
}

/** Brute force: every triangle tested, the nearest hit kept. The count is always the model's triangle count. */
export function bruteForceMeshTests(accel: MeshAccel, o: Vector3, d: Vector3, tMax: number): MeshTests {
  return walkMesh(accel, o, d, tMax, (counter, _root, triangles) => counter.nearestOf(0, triangles));
}

/** Runs `search` for the object-space ray o + t·d on a fresh counter; its tests and nearest hit. */
function walkMesh(
  accel: MeshAccel,
  o: Vector3,
  d: Vector3,
  tMax: number,
  search: (counter: MeshTestCounter, root: BvhNode, triangles: number) => TriangleHit | null,
): MeshTests {
  const tree = bvhTree(accel.bvh);
  // As intersectMesh: three-mesh-bvh measures along a unit direction.
  const scale = d.length();
  unitRay.origin.copy(o);
  unitRay.direction.copy(d).divideScalar(scale);
  const counter = new MeshTestCounter(accel, unitRay, tMax * scale);
  const hit = search(counter, tree.root, tree.triangles);
  return {
    boxes: counter.visits.length,
    triangles: counter.triangles,
    bruteForce: tree.triangles,
    t: hit ? hit.distance / scale : Infinity,
    visits: counter.visits,
  };
}

/**
 * The tests a world-space ray costs in a prepared scene, as the tracer finds a primary
 * ray's nearest hit: every object's bounding box is tested (slab test), and only an object
 * whose box the ray meets before the nearest hit so far is intersected; for a mesh, that
 * means walking its BVH. `meshes` must be the library the scene was built from.
 */
export function countRayTests(scene: TracerScene, meshes: MeshLibrary, ray: Ray): RayTests {
  const hit = new Hit();
  const result: RayTests = { objects: [], boundsTests: 0, triangles: 0, bruteForce: 0, hitId: null };
  for (const shape of scene.shapes) {
    const object = scene.source.objects.find((candidate) => candidate.id === shape.id);
    const model = object?.shape === 'mesh' && object.mesh !== undefined ? meshes.get(object.mesh) : undefined;
    const boundsHit = rayMeetsBox(ray, shape.worldBounds, hit.t);
    result.boundsTests++;
    let mesh: MeshTests | null = null;
    if (object && model) {
      const accel = meshAccel(model);
      // Into object space as Shape.intersect does: the direction is not renormalized.
      const toLocal = objectToWorld(object).invert();
      const o = ray.origin.clone().applyMatrix4(toLocal);
      const d = ray.direction.clone().applyMatrix3(new Matrix3().setFromMatrix4(toLocal));
      mesh = boundsHit ? countMeshTests(accel, o, d, hit.t) : { boxes: 0, triangles: 0, bruteForce: bvhTree(accel.bvh).triangles, t: Infinity, visits: [] };
      result.triangles += mesh.triangles;
      result.bruteForce += mesh.bruteForce;
    }
    result.objects.push({ id: shape.id, boundsHit, mesh });
    // The tracer's own test decides the nearest hit, which limits the objects after it.
    if (shape.intersect(ray, hit)) result.hitId = shape.id;
  }
  return result;
}

/**
 * The tests of the primary ray through the centre of pixel (column, row) of the camera's
 * screen (`camera.pixels`; row 0 at the top): the ray the lab draws for that pixel without
 * supersampling.
 */
export function countPixelTests(scene: TracerScene, meshes: MeshLibrary, [column, row]: readonly [number, number]): RayTests {
  const [columns, rows] = scene.source.camera.pixels;
  const direction = scene.camera.direction(column + 0.5, row + 0.5, columns, rows, new Vector3());
  return countRayTests(scene, meshes, new Ray().set(scene.camera.eye, direction));
}

/** Slab test (Kay & Kajiya 1986), as the tracer's Shape does before intersecting: is the box met before tMax? */
function rayMeetsBox(ray: Ray, box: Box3, tMax: number): boolean {
  let near = -Infinity;
  let far = Infinity;
  for (const axis of ['x', 'y', 'z'] as const) {
    const t0 = (box.min[axis] - ray.origin[axis]) * ray.inverseDirection[axis];
    const t1 = (box.max[axis] - ray.origin[axis]) * ray.inverseDirection[axis];
    near = Math.max(near, Math.min(t0, t1));
    far = Math.min(far, Math.max(t0, t1));
  }
  return !(near > far || far < 0 || near > tMax);
}

/** A nearest hit: its distance along the unit ray and its point in object space. */
interface TriangleHit {
  distance: number;
  point: Vector3;
}

/** The raycastFirst walk of one ray, counting as it goes. */
class MeshTestCounter {
  readonly visits: BoxVisit[] = [];
  triangles = 0;

  constructor(
    private readonly accel: MeshAccel,
    private readonly ray: ThreeRay,
    private readonly far: number,
  ) {}

  /** three-mesh-bvh's intersectsNodeBounds: the box test with (near, far) = (0, far). */
  meetsBox(node: BvhNode): boolean {
    const entered = this.slab(node.bounds);
    this.visits.push({ node, entered });
    return entered;
  }

  private slab(box: Float32Array): boolean {
    const { origin, direction } = this.ray;
    let near = -Infinity;
    let far = Infinity;
    for (let axis = 0; axis < 3; axis++) {
      const inverse = 1 / direction.getComponent(axis);
      const start = origin.getComponent(axis);
      const lo = (box[inverse >= 0 ? axis : axis + 3] - start) * inverse;
      const hi = (box[inverse >= 0 ? axis + 3 : axis] - start) * inverse;
      if (near > hi || lo > far) return false;
      // NaN (0 × ∞: a ray in a slab's plane) leaves the interval as it was, as in three-mesh-bvh.
      if (lo > near || Number.isNaN(near)) near = lo;
      if (hi < far || Number.isNaN(far)) far = hi;
    }
    return near <= this.far && far >= 0;
  }

  /** The nearest hit below `node`, whose box the ray meets. */
  nearest(node: BvhNode): TriangleHit | null {
    if (!node.left || !node.right) return this.nearestOf(node.offset, node.count);
    const axis = node.splitAxis;
    const forward = this.ray.direction.getComponent(axis) >= 0;
    const [first, second] = forward ? [node.left, node.right] : [node.right, node.left];
    const firstHit = this.meetsBox(first) ? this.nearest(first) : null;
    if (firstHit) {
      // A hit before the second box begins along the split axis cannot be beaten there.
      const along = firstHit.point.getComponent(axis);
      if (forward ? along <= second.bounds[axis] : along >= second.bounds[axis + 3]) return firstHit;
    }
    const secondHit = this.meetsBox(second) ? this.nearest(second) : null;
    if (firstHit && secondHit) return firstHit.distance <= secondHit.distance ? firstHit : secondHit;
    return firstHit ?? secondHit;
  }

  /** Tests triangles offset … offset + count − 1 (double-sided, as the tracer casts); the nearest hit. */
  nearestOf(offset: number, count: number): TriangleHit | null {
    const { index, positions } = this.accel;
    let best: TriangleHit | null = null;
    for (let i = offset; i < offset + count; i++) {
      this.triangles++;
      a.fromArray(positions, index[i * 3] * 3);
      b.fromArray(positions, index[i * 3 + 1] * 3);
      c.fromArray(positions, index[i * 3 + 2] * 3);
      if (!this.ray.intersectTriangle(a, b, c, false, point)) continue;
      const distance = this.ray.origin.distanceTo(point);
      if (distance > this.far || (best && distance >= best.distance)) continue;
      best = { distance, point: point.clone() };
    }
    return best;
  }
}
