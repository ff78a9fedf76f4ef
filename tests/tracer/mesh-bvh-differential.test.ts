import { TorusKnotGeometry, Vector3 } from 'three';
import { describe, expect, it } from 'vitest';
import type { MeshData } from '../../src/scene/mesh-data.ts';
import { Hit } from '../../src/tracer/hit.ts';
import { Ray } from '../../src/tracer/ray.ts';
import { hashKey, RandomStream } from '../../src/tracer/sampler.ts';
import { objectToWorld } from '../../src/tracer/tracer-scene.ts';
import { matte, tracerSceneFrom } from '../support/test-scene.ts';

/** Möller–Trumbore ray/triangle test (1997), both faces: the brute-force oracle. */
function intersectTriangle(o: Vector3, d: Vector3, a: Vector3, b: Vector3, c: Vector3): number | null {
  const e1 = new Vector3().subVectors(b, a);
  const e2 = new Vector3().subVectors(c, a);
  const p = new Vector3().crossVectors(d, e2);
  const det = e1.dot(p);
  if (Math.abs(det) < 1e-12) return null;
  const s = new Vector3().subVectors(o, a);
  const u = s.dot(p) / det;
  if (u < 0 || u > 1) return null;
  const q = new Vector3().crossVectors(s, e1);
  const v = d.dot(q) / det;
  if (v < 0 || u + v > 1) return null;
  const t = e2.dot(q) / det;
  return t > 0 ? t : null;
}

function torusKnot(): MeshData {
  const geometry = new TorusKnotGeometry(0.3, 0.1, 96, 12);
  return {
    positions: geometry.getAttribute('position').array as Float32Array,
    normals: geometry.getAttribute('normal').array as Float32Array,
    indices: new Uint32Array(geometry.getIndex()!.array),
  };
}

describe('mesh intersection through the BVH', () => {
  it('finds the same nearest hits as testing every triangle, on 3000 random rays', () => {
    const mesh = torusKnot();
    const placement = { position: [0.3, -0.2, 0.1], rotation: [20, 40, -10], scale: [1.5, 0.8, 1.2] } as const;
    const scene = tracerSceneFrom(
      { objects: [{ id: 'knot', shape: 'mesh', mesh: 'character', ...placement, material: matte([1, 1, 1]) }] },
      new Map([['character', mesh]]),
    );
    const shape = scene.shapes[0];
    const toWorld = objectToWorld({ position: [...placement.position], rotation: [...placement.rotation], scale: [...placement.scale] });
    const triangles: Vector3[][] = [];
    for (let i = 0; i < mesh.indices.length; i += 3) {
      triangles.push([0, 1, 2].map((k) => new Vector3().fromArray(mesh.positions, mesh.indices[i + k] * 3).applyMatrix4(toWorld)));
    }

    const random = new RandomStream().reset(hashKey(2024));
    let hits = 0;
    let disagreements = 0;
    for (let i = 0; i < 3000; i++) {
      // From a random point around the knot toward a random point inside its bounds.
      const origin = new Vector3(random.next() - 0.5, random.next() - 0.5, random.next() - 0.5).multiplyScalar(4);
      const target = new Vector3(random.next() - 0.5, random.next() - 0.5, random.next() - 0.5).add(new Vector3(0.3, -0.2, 0.1));
      const direction = target.sub(origin).normalize();
      let nearest = Infinity;
      for (const [a, b, c] of triangles) nearest = Math.min(nearest, intersectTriangle(origin, direction, a, b, c) ?? Infinity);
      const hit = new Hit().reset(Infinity);
      shape.intersect(new Ray().set(origin, direction), hit);
      if (nearest === Infinity || hit.t === Infinity) {
        // A ray grazing a shared edge may be caught by one test and not the other.
        if (nearest !== hit.t) disagreements++;
        continue;
      }
      hits++;
      expect(Math.abs(hit.t - nearest)).toBeLessThan(1e-5 * nearest);
    }
    expect(hits).toBeGreaterThan(1000);
    expect(disagreements).toBeLessThanOrEqual(3);
  });

  it('reports the outward, unit, interpolated normal at the hit', () => {
    const knot = torusKnot();
    const scene = tracerSceneFrom(
      { objects: [{ id: 'knot', shape: 'mesh', mesh: 'character', scale: [2, 2, 2], material: matte([1, 1, 1]) }] },
      new Map([['character', knot]]),
    );
    // From far in front, toward the vertex that faces the viewer most (the knot has a hole
    // in its middle, and at a silhouette an interpolated normal may turn slightly away).
    let facing = 0;
    for (let i = 0; i < knot.normals!.length / 3; i++) if (knot.normals![i * 3 + 2] > knot.normals![facing * 3 + 2]) facing = i;
    const vertex = new Vector3().fromArray(knot.positions, facing * 3).multiplyScalar(2);
    const ray = new Ray().set(vertex.clone().add(new Vector3(0, 0, 5)), new Vector3(0, 0, -1));
    const hit = new Hit().reset(Infinity);
    expect(scene.shapes[0].intersect(ray, hit)).toBe(true);
    scene.shapes[0].surface(ray, hit);
    expect(hit.normal.length()).toBeCloseTo(1, 10);
    expect(hit.geometricNormal.length()).toBeCloseTo(1, 10);
    // Hit from outside: the outward normals face back along the ray.
    expect(hit.geometricNormal.dot(ray.direction)).toBeLessThan(0);
    expect(hit.normal.dot(ray.direction)).toBeLessThan(0);
  });

  it('a scene naming a model that was not loaded is refused with a clear message', () => {
    expect(() => tracerSceneFrom({ objects: [{ id: 'glass', shape: 'mesh', mesh: 'wine-glass' }] })).toThrow(
      'objects[0] ("glass"): the model "wine-glass" was not loaded',
    );
  });
});
