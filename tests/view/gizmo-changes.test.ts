import { Quaternion, Vector3 } from 'three';
import { describe, expect, it } from 'vitest';
import { createLight, defaultScene } from '../../src/scene/scene-defaults.ts';
import type { AreaLight, Camera } from '../../src/scene/scene.ts';
import { cameraChanges, eulerDegrees, lightChanges, objectChanges, roundToStep } from '../../src/view/gizmo-changes.ts';
import { sceneQuaternion } from '../../src/tracer/scene-rotation.ts';

function pose(position: [number, number, number], degrees: [number, number, number], scale: [number, number, number] = [1, 1, 1]) {
  return {
    position: new Vector3(...position),
    quaternion: sceneQuaternion(degrees),
    scale: new Vector3(...scale),
  };
}

describe('gizmo drag → action payload', () => {
  it('rounds to clean numbers: no float noise, no −0', () => {
    expect(roundToStep(0.1 + 0.2, 1e-4)).toBe(0.3);
    expect(roundToStep(-0.00001, 1e-4)).toBe(0);
    expect(Object.is(roundToStep(-0.00001, 1e-4), -0)).toBe(false);
    expect(roundToStep(0.37, 0.25)).toBe(0.25);
    expect(roundToStep(44.9999999, 15)).toBe(45);
  });

  it('turns three.js radians back into the scene file’s Euler XYZ degrees', () => {
    const { rotation } = objectChanges(pose([0, 0, 0], [30, -45, 120]), false);
    expect(rotation).toEqual([30, -45, 120]);
    expect(eulerDegrees(new Quaternion().setFromAxisAngle(new Vector3(0, 1, 0), Math.PI / 2), false)).toEqual([0, 90, 0]);
  });

  it('never gives −180: a half turn is +180', () => {
    expect(eulerDegrees(new Quaternion().setFromAxisAngle(new Vector3(0, 0, 1), -Math.PI), false)[2]).toBe(180);
  });

  it('snaps to 0.25 m, 15° and 0.25× when snapping, and keeps 0.1 mm / 0.01° otherwise', () => {
    const dragged = pose([1.13, 0.49, -2.374], [0, 37, 0], [1.38, 0.9, 2.1]);
    expect(objectChanges(dragged, true)).toEqual({ position: [1.25, 0.5, -2.25], rotation: [0, 30, 0], scale: [1.5, 1, 2] });
    expect(objectChanges(dragged, false)).toEqual({ position: [1.13, 0.49, -2.374], rotation: [0, 37, 0], scale: [1.38, 0.9, 2.1] });
  });

  it('keeps scales positive (the scene refuses 0 and below): a gizmo dragged through zero stops at the smallest scale', () => {
    expect(objectChanges(pose([0, 0, 0], [0, 0, 0], [-0.4, 0, 0.00001]), false).scale).toEqual([0.001, 0.001, 0.001]);
    expect(objectChanges(pose([0, 0, 0], [0, 0, 0], [0.05, 1, 1]), true).scale).toEqual([0.25, 1, 1]);
  });

  it('writes only a position for a point light, position and rotation for a spot', () => {
    const scene = defaultScene();
    const [lamp, spot] = scene.lights;
    expect(lightChanges(lamp!, pose([1, 2, 3], [10, 0, 0]), false)).toEqual({ position: [1, 2, 3] });
    expect(lightChanges(spot!, pose([1, 2, 3], [10, 0, 0]), false)).toEqual({ position: [1, 2, 3], rotation: [10, 0, 0] });
  });

  it('turns an area light’s gizmo scale into its size (width along x, depth along z)', () => {
    const area = { ...createLight('area', defaultScene()), size: [2, 1] } as AreaLight;
    const changes = lightChanges(area, pose([0, 3, 0], [0, 0, 0], [1.5, 7, 0.5]), false);
    expect(changes).toEqual({ position: [0, 3, 0], rotation: [0, 0, 0], size: [3, 0.5] });
  });

  it('turns the camera’s target with it and keeps the distance to it', () => {
    const camera: Camera = { position: [0, 1, 5], target: [0, 1, 1], fov: 45, pixels: [8, 6], screenDistance: 1, aperture: 0, lensSamples: 1 };
    // The rig looks down its local −z; turned 90° left about +Y it looks down world −x.
    const changes = cameraChanges(camera, pose([2, 1, 5], [0, 90, 0]), false);
    expect(changes.position).toEqual([2, 1, 5]);
    expect(changes.target).toEqual([-2, 1, 5]);
  });

  it('aims the target from the snapped position, so snapping keeps the distance too', () => {
    const camera: Camera = { position: [0, 0, 0], target: [0, 0, -2], fov: 45, pixels: [8, 6], screenDistance: 1, aperture: 0, lensSamples: 1 };
    const changes = cameraChanges(camera, pose([0.1, 0.2, 0.05], [0, 0, 0]), true);
    expect(changes).toEqual({ position: [0, 0.25, 0], target: [0, 0.25, -2] });
  });
});
