import { Box3, Ray as ThreeRay, Vector3 } from 'three';
import { beforeAll, describe, expect, it } from 'vitest';
import { loadMeshesFromDisk } from '../../src/scene/load-meshes-node.ts';
import type { MeshData } from '../../src/scene/mesh-data.ts';
import { type BvhNode, bvhTree } from '../../src/tracer/bvh-tree.ts';
import { hashKey, RandomStream } from '../../src/tracer/sampler.ts';
import { meshAccel } from '../../src/tracer/shapes/mesh-accel.ts';
import { countMeshTests } from '../../src/tracer/triangle-test-count.ts';

let character: MeshData;

beforeAll(async () => {
  character = (await loadMeshesFromDisk(['character'])).get('character')!;
});

/** Brute force: does the ray meet the node's box at all (three.js's own ray–box test, no BVH walk)? */
function meetsBox(ray: ThreeRay, node: BvhNode): boolean {
  const b = node.bounds;
  return ray.intersectsBox(new Box3(new Vector3(b[0], b[1], b[2]), new Vector3(b[3], b[4], b[5])));
}

/** Brute force: the nearest triangle (in the BVH's order) the ray hits, by testing all of them. */
function nearestTriangle(ray: ThreeRay): number {
  const { index, positions } = meshAccel(character);
  const [a, b, c, point] = [new Vector3(), new Vector3(), new Vector3(), new Vector3()];
  let best = -1;
  let bestDistance = Infinity;
  for (let i = 0; i < index.length / 3; i++) {
    a.fromArray(positions, index[i * 3] * 3);
    b.fromArray(positions, index[i * 3 + 1] * 3);
    c.fromArray(positions, index[i * 3 + 2] * 3);
    if (!ray.intersectTriangle(a, b, c, false, point)) continue;
    const distance = ray.origin.distanceTo(point);
    if (distance < bestDistance) [best, bestDistance] = [i, distance];
  }
  return best;
}

describe('the boxes one ray entered and skipped in the BVH', () => {
  it('agree with a brute-force box test, follow the tree, and lead to the nearest triangle', () => {
    const accel = meshAccel(character);
    const tree = bvhTree(accel.bvh);
    const parents = new Map<BvhNode, BvhNode>();
    const link = (node: BvhNode) => {
      for (const child of [node.left, node.right])
        if (child) {
          parents.set(child, node);
          link(child);
        }
    };
    link(tree.root);
    const random = new RandomStream().reset(hashKey(16, 9));
    let hits = 0;
    let skipped = 0;
    for (let i = 0; i < 60; i++) {
      const along = () => random.next() * 2 - 1;
      const o = new Vector3(along(), along(), along()).normalize().multiplyScalar(3);
      const d = new Vector3(along() * 0.3, along() * 0.5, along() * 0.2).sub(o).normalize();
      const ray = new ThreeRay(o, d);
      const { visits, boxes, t } = countMeshTests(accel, o, d, Infinity);
      expect(boxes).toBe(visits.length);
      expect(visits[0]!.node).toBe(tree.root);
      const entered = new Set(visits.filter((v) => v.entered).map((v) => v.node));
      expect(new Set(visits.map((v) => v.node)).size).toBe(visits.length);
      for (const { node, entered: inside } of visits) {
        // Each test's answer is the brute-force one…
        expect(inside).toBe(meetsBox(ray, node));
        // …and a box is only tested inside one the ray entered.
        if (node !== tree.root) expect(entered.has(parents.get(node)!)).toBe(true);
      }
      // Both children of an entered box are tested, unless a hit in the near one already beat the far one.
      for (const node of entered)
        if (node.left && node.right) {
          const tested = [node.left, node.right].filter((child) => visits.some((v) => v.node === child));
          expect(tested.length).toBeGreaterThanOrEqual(1);
          if (tested.length === 1) skipped++;
        }
      skipped += visits.filter((v) => !v.entered).length;
      const nearest = nearestTriangle(ray);
      expect(nearest >= 0).toBe(t < Infinity);
      if (nearest < 0) continue;
      hits++;
      // The leaf holding the nearest triangle, and every box above it, were entered.
      const leaf = [...parents.keys(), tree.root].find((n) => !n.left && n.offset <= nearest && nearest < n.offset + n.count)!;
      for (let node: BvhNode | undefined = leaf; node; node = parents.get(node)) expect(entered.has(node)).toBe(true);
    }
    expect(hits).toBeGreaterThan(15);
    expect(skipped).toBeGreaterThan(60);
  });
});
