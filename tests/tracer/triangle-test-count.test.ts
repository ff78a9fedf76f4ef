import { issueLine } from '../../src/util/issue.ts';
import { DoubleSide, Ray as ThreeRay, Vector3 } from 'three';
import { beforeAll, describe, expect, it } from 'vitest';
import { loadMeshesFromDisk } from '../../src/scene/load-meshes-node.ts';
import type { MeshData, MeshLibrary } from '../../src/scene/mesh-data.ts';
import { parseScene } from '../../src/scene/scene-schema.ts';
import { bvhTree, nodesAtDepth } from '../../src/tracer/bvh-tree.ts';
import { Ray } from '../../src/tracer/ray.ts';
import { meshAccel } from '../../src/tracer/shapes/mesh-accel.ts';
import { buildTracerScene } from '../../src/tracer/tracer-scene.ts';
import { bruteForceMeshTests, countMeshTests, countRayTests } from '../../src/tracer/triangle-test-count.ts';
import { hashKey, RandomStream } from '../../src/tracer/sampler.ts';

let meshes: MeshLibrary;
let character: MeshData;

beforeAll(async () => {
  meshes = await loadMeshesFromDisk(['character']);
  character = meshes.get('character')!;
});

/** A random ray from a point around the model towards a point inside its box. */
function randomRay(random: RandomStream): { o: Vector3; d: Vector3 } {
  const along = () => random.next() * 2 - 1;
  const o = new Vector3(along(), along(), along()).normalize().multiplyScalar(3);
  const target = new Vector3(along() * 0.3, along() * 0.5, along() * 0.2);
  return { o, d: target.sub(o).normalize() };
}

describe('the BVH as plain nodes', () => {
  it('covers every triangle exactly once, in leaves inside their parents', () => {
    const tree = bvhTree(meshAccel(character).bvh);
    expect(tree.triangles).toBe(8624);
    const covered = new Uint8Array(tree.triangles);
    const visit = (node: typeof tree.root, parent: Float32Array | null) => {
      if (parent)
        for (let axis = 0; axis < 3; axis++) {
          expect(node.bounds[axis]).toBeGreaterThanOrEqual(parent[axis]);
          expect(node.bounds[axis + 3]).toBeLessThanOrEqual(parent[axis + 3]);
        }
      if (node.left && node.right) {
        visit(node.left, node.bounds);
        visit(node.right, node.bounds);
      } else {
        for (let i = node.offset; i < node.offset + node.count; i++) covered[i]++;
      }
    };
    visit(tree.root, null);
    expect(covered.every((count) => count === 1)).toBe(true);
    expect(tree.maxDepth).toBeGreaterThan(8);
  });

  it('depth 0 is the whole model; deeper levels split it into more, smaller boxes', () => {
    const tree = bvhTree(meshAccel(character).bvh);
    expect(nodesAtDepth(tree, 0)).toEqual([tree.root]);
    expect(nodesAtDepth(tree, 1)).toEqual([tree.root.left, tree.root.right]);
    expect(nodesAtDepth(tree, 3)).toHaveLength(8);
    const leaves = nodesAtDepth(tree, 99);
    expect(leaves.every((node) => node.left === null && node.count > 0)).toBe(true);
    expect(leaves.reduce((sum, node) => sum + node.count, 0)).toBe(8624);
  });
});

describe('counting the tests of one ray against a model', () => {
  it('tests exactly the triangles the tracer’s raycastFirst tests, finds its nearest hit, and far fewer than brute force', () => {
    const accel = meshAccel(character);
    const random = new RandomStream().reset(hashKey(15, 16));
    let hits = 0;
    for (let i = 0; i < 400; i++) {
      const { o, d } = randomRay(random);
      const counted = countMeshTests(accel, o, d, Infinity);
      const brute = bruteForceMeshTests(accel, o, d, Infinity);
      // The oracle: the tracer's own cast, its triangle tests counted where they happen.
      const cast = new ThreeRay(o, d);
      let tracerTests = 0;
      const intersectTriangle = cast.intersectTriangle.bind(cast);
      cast.intersectTriangle = (...args) => {
        tracerTests++;
        return intersectTriangle(...args);
      };
      const tracer = accel.bvh.raycastFirst(cast, DoubleSide, 0, Infinity);
      expect(counted.triangles).toBe(tracerTests);
      expect(brute.triangles).toBe(8624);
      expect(counted.bruteForce).toBe(8624);
      if (tracer) {
        hits++;
        expect(counted.t).toBeCloseTo(tracer.distance, 6);
        expect(brute.t).toBeCloseTo(tracer.distance, 6);
      } else {
        expect(counted.t).toBe(Infinity);
        expect(brute.t).toBe(Infinity);
      }
      expect(counted.triangles).toBeLessThan(8624 / 10);
    }
    // The rays aim at the model's box: many hit, some pass by.
    expect(hits).toBeGreaterThan(100);
    expect(hits).toBeLessThan(400);
  });

  it('a ray that misses the model’s box tests one box and no triangle', () => {
    const accel = meshAccel(character);
    const counted = countMeshTests(accel, new Vector3(0, 5, 5), new Vector3(0, 0, -1), Infinity);
    expect(counted).toEqual({ boxes: 1, triangles: 0, bruteForce: 8624, t: Infinity, visits: [{ node: bvhTree(accel.bvh).root, entered: false }] });
  });

  it('a ray through the middle of the body stops early: a few leaves, not the triangles behind the hit', () => {
    const counted = countMeshTests(meshAccel(character), new Vector3(0, 0, 3), new Vector3(0, 0, -1), Infinity);
    expect(counted.t).toBeLessThan(3);
    expect(counted.triangles).toBeGreaterThan(0);
    expect(counted.triangles).toBeLessThan(200);
    expect(counted.boxes).toBeGreaterThan(counted.triangles / 4);
  });

  it('scales the direction as the tracer does: t along an unnormalized direction', () => {
    const accel = meshAccel(character);
    const unit = countMeshTests(accel, new Vector3(0, 0, 3), new Vector3(0, 0, -1), Infinity);
    const doubled = countMeshTests(accel, new Vector3(0, 0, 3), new Vector3(0, 0, -2), Infinity);
    expect(doubled.t).toBeCloseTo(unit.t / 2, 9);
    expect(doubled.triangles).toBe(unit.triangles);
  });
});

describe('counting the tests of one ray against a scene', () => {
  function scene() {
    const parsed = parseScene({
      version: 1,
      objects: [
        { id: 'ball', shape: 'sphere', position: [-1.5, 0.5, 0] },
        { id: 'hero', shape: 'mesh', mesh: 'character', position: [0, 0.9, 0], scale: [1.8, 1.8, 1.8], rotation: [0, 30, 0] },
        { id: 'crate', shape: 'box', position: [1.5, 0.5, 0] },
      ],
      lights: [{ id: 'lamp', position: [2, 4, 3] }],
    });
    if (!parsed.ok) throw new Error(parsed.errors.map(issueLine).join('\n'));
    return buildTracerScene(parsed.scene, meshes);
  }
  const ray = (origin: Vector3, target: Vector3) => new Ray().set(origin, target.clone().sub(origin).normalize());

  it('tests every object’s box once; a ray above everything tests no triangle at all', () => {
    const tests = countRayTests(scene(), meshes, ray(new Vector3(0, 5, 5), new Vector3(0, 5, -5)));
    expect(tests.boundsTests).toBe(3);
    expect(tests.objects.map((o) => o.boundsHit)).toEqual([false, false, false]);
    expect(tests).toMatchObject({ triangles: 0, bruteForce: 8624, hitId: null });
  });

  it('a ray at the character tests its BVH, and the same count as the model on its own', () => {
    const traced = scene();
    const tests = countRayTests(traced, meshes, ray(new Vector3(0, 1, 4), new Vector3(0, 1, 0)));
    expect(tests.hitId).toBe('hero');
    expect(tests.objects.map((o) => o.boundsHit)).toEqual([false, true, false]);
    const hero = tests.objects[1].mesh!;
    expect(hero.triangles).toBe(tests.triangles);
    expect(hero.triangles).toBeGreaterThan(0);
    expect(hero.triangles).toBeLessThan(300);
  });

  it('an object behind the nearest hit is not even opened: its box lies beyond the hit', () => {
    const traced = scene();
    // From the left, through the ball first and then towards the character behind it.
    const tests = countRayTests(traced, meshes, ray(new Vector3(-5, 0.5, 0), new Vector3(0, 0.5, 0)));
    expect(tests.hitId).toBe('ball');
    expect(tests.objects[1]).toMatchObject({ id: 'hero', boundsHit: false, mesh: { triangles: 0 } });
  });
});
