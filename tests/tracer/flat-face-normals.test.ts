import { Euler, Vector3 } from 'three';
import { describe, expect, it } from 'vitest';
import { Hit } from '../../src/tracer/hit.ts';
import { Ray } from '../../src/tracer/ray.ts';
import { matte, tracerSceneFrom } from '../support/test-scene.ts';

/** The shape's only object, hit by a ray from `from` toward `to`: its world normals. */
function normalsAt(object: Record<string, unknown>, from: Vector3, to: Vector3): Hit {
  const scene = tracerSceneFrom({
    camera: { position: [0, 0, 10], target: [0, 0, 0], fov: 30, pixels: [8, 8] },
    objects: [{ id: 'thing', material: matte([1, 1, 1]), ...object }],
    lights: [],
  });
  const ray = new Ray().set(from, to.clone().sub(from).normalize());
  const hit = new Hit().reset(Infinity);
  scene.objects.nearest(ray, hit, null);
  expect(hit.shape).not.toBeNull();
  hit.shape!.surface(ray, hit);
  return hit;
}

// A box and a plane turned on all three axes and stretched unevenly: a face's normal is the
// rotation of the unit face's normal (a scale along the face's own axes does not turn it).
const rotation: [number, number, number] = [25, -40, 70];
const [rx, ry, rz] = rotation.map((degrees) => (degrees * Math.PI) / 180);
const turn = new Euler(rx, ry, rz, 'XYZ');

describe('the world normals of flat faces', () => {
  it.each([
    ['+x', [1, 0, 0]],
    ['−x', [-1, 0, 0]],
    ['+y', [0, 1, 0]],
    ['−y', [0, -1, 0]],
    ['+z', [0, 0, 1]],
    ['−z', [0, 0, -1]],
  ] as const)("are a turned box's %s face's outward normal", (_, axis) => {
    const outward = new Vector3(...axis).applyEuler(turn);
    const hit = normalsAt(
      { shape: 'box', position: [0.5, -0.25, 0], rotation, scale: [1.5, 0.8, 1.2] },
      outward
        .clone()
        .multiplyScalar(6)
        .add(new Vector3(0.5, -0.25, 0)),
      new Vector3(0.5, -0.25, 0),
    );
    expect(hit.geometricNormal.distanceTo(outward)).toBeLessThan(1e-12);
    expect(hit.normal.equals(hit.geometricNormal)).toBe(true);
  });

  it("is a turned plane's normal on both of its sides", () => {
    const up = new Vector3(0, 1, 0).applyEuler(turn);
    for (const side of [1, -1]) {
      const hit = normalsAt({ shape: 'plane', rotation, scale: [3, 1, 2] }, up.clone().multiplyScalar(4 * side), new Vector3());
      // The plane's normal is its own, whichever side the ray comes from: the integrators turn it.
      expect(hit.geometricNormal.distanceTo(up)).toBeLessThan(1e-12);
      expect(hit.normal.equals(hit.geometricNormal)).toBe(true);
    }
  });
});
