import { BackSide, Box3, type BufferGeometry, FrontSide, LineSegments, Mesh, type MeshBasicMaterial, type Object3D, Vector3 } from 'three';
import { describe, expect, it } from 'vitest';
import { sceneFrom } from '../support/test-scene.ts';
import type { Scene } from '../../src/scene/scene.ts';
import { TracerLight } from '../../src/tracer/lights.ts';
import { LightGizmos, SPOT_CONE_SLANT } from '../../src/view/light-gizmos.ts';

function sceneWith(lights: Record<string, unknown>[], lightTypes = { point: true, spot: true, area: true }): Scene {
  return sceneFrom({ objects: [], lights, settings: { lightTypes } });
}

function meshes(root: Object3D): Mesh<BufferGeometry, MeshBasicMaterial>[] {
  const found: Mesh<BufferGeometry, MeshBasicMaterial>[] = [];
  root.traverse((node) => {
    if (node instanceof Mesh) found.push(node as Mesh<BufferGeometry, MeshBasicMaterial>);
  });
  return found;
}

/** The world positions of a line object's vertices. */
function linePoints(line: LineSegments): Vector3[] {
  line.updateWorldMatrix(true, false);
  const position = line.geometry.getAttribute('position');
  return Array.from({ length: position.count }, (_, i) => new Vector3().fromBufferAttribute(position, i).applyMatrix4(line.matrixWorld));
}

describe('light gizmos', () => {
  it('draws a point light as a bulb in its colour at its position', () => {
    const gizmos = new LightGizmos();
    gizmos.sync(sceneWith([{ id: 'lamp', type: 'point', position: [1, 2, 3], color: [1, 0.5, 0] }]));
    const rig = gizmos.objectOf('lamp')!;
    expect(rig.position.toArray()).toEqual([1, 2, 3]);
    const colours = meshes(rig).map((mesh) => mesh.material.color.toArray());
    expect(colours).toContainEqual([1, 0.5, 0]);
  });

  it.each([20, 40, 90, 170])('opens a %i° spot light’s cone by half that angle around the direction the tracer uses', (spotAngle) => {
    const light = { id: 'spot', type: 'spot', position: [0, 3, 0], rotation: [35, 20, -10], spotAngle };
    const scene = sceneWith([light]);
    const gizmos = new LightGizmos();
    gizmos.sync(scene);
    const direction = new TracerLight(scene.lights[0]!).direction;
    let edges: LineSegments | null = null;
    gizmos.objectOf('spot')!.traverse((node) => {
      if (node instanceof LineSegments) edges = node;
    });
    const points = linePoints(edges!);
    // The last 8 points are the four lines from the apex to the base circle.
    const apexLines = points.slice(-8);
    for (let i = 0; i < 8; i += 2) {
      const apex = apexLines[i]!;
      const rim = apexLines[i + 1]!.clone().sub(apex);
      expect(apex.distanceTo(new Vector3(0, 3, 0))).toBeLessThan(1e-9);
      expect(rim.length()).toBeCloseTo(SPOT_CONE_SLANT, 6);
      expect((rim.angleTo(direction) * 180) / Math.PI).toBeCloseTo(spotAngle / 2, 4);
    }
  });

  it('draws an area light in its local XZ plane: lit face toward the tracer’s direction in its colour, back face black', () => {
    const light = { id: 'panel', type: 'area', position: [0, 3, 0], rotation: [0, 0, 30], size: [2, 0.5], color: [0.2, 0.6, 1] };
    const scene = sceneWith([light]);
    const gizmos = new LightGizmos();
    gizmos.sync(scene);
    const direction = new TracerLight(scene.lights[0]!).direction;
    const [front, back] = meshes(gizmos.objectOf('panel')!);
    expect(front!.material.side).toBe(FrontSide);
    expect(front!.material.color.toArray()).toEqual([0.2, 0.6, 1]);
    expect(back!.material.side).toBe(BackSide);
    expect(back!.material.color.toArray()).toEqual([0, 0, 0]);
    front!.updateWorldMatrix(true, false);
    const normal = new Vector3().fromBufferAttribute(front!.geometry.getAttribute('normal'), 0).transformDirection(front!.matrixWorld);
    expect(normal.distanceTo(direction)).toBeLessThan(1e-6);
    // Its size: 2 m along its local x, 0.5 m along z.
    const box = new Box3().setFromObject(front!);
    const size = box.getSize(new Vector3());
    expect(Math.hypot(size.x, size.y)).toBeGreaterThan(1.9);
    expect(size.z).toBeCloseTo(0.5, 6);
  });

  it('edits a spot angle or colour change in place (no new geometry or material), and rebuilds only for a new type', () => {
    const gizmos = new LightGizmos();
    let scene = sceneWith([{ id: 'spot', type: 'spot', position: [0, 3, 0], spotAngle: 30 }]);
    gizmos.sync(scene);
    const rig = gizmos.objectOf('spot')!;
    const parts = meshes(rig).map((mesh) => [mesh.geometry, mesh.material]);
    scene = sceneWith([{ id: 'spot', type: 'spot', position: [0, 3, 0], spotAngle: 120, color: [1, 0, 0] }]);
    gizmos.sync(scene);
    expect(gizmos.objectOf('spot')).toBe(rig);
    expect(meshes(rig).map((mesh) => [mesh.geometry, mesh.material])).toEqual(parts);
    let disposed = 0;
    for (const mesh of meshes(rig)) mesh.material.addEventListener('dispose', () => disposed++);
    gizmos.sync(sceneWith([{ id: 'spot', type: 'point', position: [0, 3, 0] }]));
    expect(gizmos.objectOf('spot')).not.toBe(rig);
    expect(disposed).toBeGreaterThan(0);
    gizmos.sync(sceneWith([]));
    expect(gizmos.group.children).toHaveLength(0);
  });

  it('fades a light whose type the ray tracer has switched off, and brings it back', () => {
    const gizmos = new LightGizmos();
    const light = { id: 'lamp', type: 'point', position: [0, 3, 0], color: [1, 1, 0] };
    gizmos.sync(sceneWith([light], { point: false, spot: true, area: true }));
    const bulb = meshes(gizmos.objectOf('lamp')!).find((mesh) => mesh.material.color.b < 0.9 && mesh.material.transparent)!;
    expect(bulb.material.opacity).toBeLessThan(1);
    gizmos.sync(sceneWith([light]));
    expect(bulb.material.color.toArray()).toEqual([1, 1, 0]);
    expect([bulb.material.transparent, bulb.material.opacity]).toEqual([false, 1]);
  });
});
