import { issueLine } from '../../src/util/issue.ts';
import { PerspectiveCamera } from 'three';
import { describe, expect, it } from 'vitest';
import { initialState, type LabState } from '../../src/lab-state/lab-state.ts';
import { reduce } from '../../src/lab-state/lab-reducer.ts';
import type { LabAction } from '../../src/lab-state/lab-action.ts';
import type { Scene } from '../../src/scene/scene.ts';
import { parseScene } from '../../src/scene/scene-schema.ts';
import { nudgeAction, nudgeNote, type ViewAxes, viewAxesOf } from '../../src/view/gizmo-nudge.ts';

function sceneOf(input: unknown): Scene {
  const parsed = parseScene(input);
  if (!parsed.ok) throw new Error(parsed.errors.map(issueLine).join('\n'));
  return parsed.scene;
}

const scene = sceneOf({
  version: 1,
  camera: { position: [0, 1.5, 5], target: [0, 0.5, 0], pixels: [8, 6] },
  objects: [{ id: 'box', shape: 'box', position: [0.9, 0.4, -0.5], rotation: [0, 30, 0], scale: [0.8, 0.8, 0.8] }],
  lights: [
    { id: 'lamp', type: 'point', position: [2, 4, 3] },
    { id: 'spot', type: 'spot', position: [0, 3, 0], rotation: [0, 0, 0] },
    { id: 'panel', type: 'area', position: [0, 3, 0], size: [1, 2] },
  ],
});
const selecting = (selection: LabState['selection']) => ({ ...initialState(scene), selection });
/** The viewer looks along −z (the level's start): right is +x. */
const fromFront: ViewAxes = { right: [1, 0, 0], forward: [0, -0.2, -0.98] };
/** The viewer looks along +x from the left, a little askew: right is +z. */
const fromLeft: ViewAxes = { right: [0.1, 0, 0.99], forward: [0.99, -0.3, -0.1] };

const changes = (action: LabAction | null) => (action as { changes: Record<string, unknown> } | null)?.changes;

describe('stepping the selection with the keys, in the gizmo’s mode', () => {
  it('moves an object 0.1 m (Shift: 0.5 m) along the world axis nearest the viewer’s right, up, or depth', () => {
    const state = selecting({ kind: 'object', id: 'box' });
    expect(changes(nudgeAction(state, { mode: 'translate', direction: 'right', big: false }, fromFront))?.position).toEqual([1, 0.4, -0.5]);
    expect(changes(nudgeAction(state, { mode: 'translate', direction: 'left', big: true }, fromFront))?.position).toEqual([0.4, 0.4, -0.5]);
    expect(changes(nudgeAction(state, { mode: 'translate', direction: 'up', big: false }, fromFront))?.position).toEqual([0.9, 0.5, -0.5]);
    expect(changes(nudgeAction(state, { mode: 'translate', direction: 'farther', big: false }, fromFront))?.position).toEqual([0.9, 0.4, -0.6]);
    expect(changes(nudgeAction(state, { mode: 'translate', direction: 'right', big: false }, fromLeft))?.position).toEqual([0.9, 0.4, -0.4]);
    // Rotation and scale stay as they were.
    expect(changes(nudgeAction(state, { mode: 'translate', direction: 'right', big: false }, fromFront))).toMatchObject({
      rotation: [0, 30, 0],
      scale: [0.8, 0.8, 0.8],
    });
  });

  it('turns an object 5° (Shift: 15°) about the vertical, or tilts it about the viewer’s right axis', () => {
    const state = selecting({ kind: 'object', id: 'box' });
    expect(changes(nudgeAction(state, { mode: 'rotate', direction: 'right', big: false }, fromFront))?.rotation).toEqual([0, 25, 0]);
    expect(changes(nudgeAction(state, { mode: 'rotate', direction: 'left', big: true }, fromFront))?.rotation).toEqual([0, 45, 0]);
    const upright = { ...state, scene: { ...scene, objects: [{ ...scene.objects[0]!, rotation: [0, 0, 0] as [number, number, number] }] } };
    expect(changes(nudgeAction(upright, { mode: 'rotate', direction: 'up', big: false }, fromFront))?.rotation).toEqual([-5, 0, 0]);
  });

  it('scales an object ×1.1 up (÷1.1 down), Shift ×1.5', () => {
    const state = selecting({ kind: 'object', id: 'box' });
    expect(changes(nudgeAction(state, { mode: 'scale', direction: 'up', big: false }, fromFront))?.scale).toEqual([0.88, 0.88, 0.88]);
    expect(changes(nudgeAction(state, { mode: 'scale', direction: 'down', big: true }, fromFront))?.scale).toEqual([0.5333, 0.5333, 0.5333]);
  });

  it('moves lights, turns a spot (its direction changes), grows an area light’s size', () => {
    expect(changes(nudgeAction(selecting({ kind: 'light', id: 'lamp' }), { mode: 'translate', direction: 'down', big: true }, fromFront))).toEqual({
      position: [2, 3.5, 3],
    });
    expect(changes(nudgeAction(selecting({ kind: 'light', id: 'spot' }), { mode: 'rotate', direction: 'down', big: true }, fromFront))?.rotation).toEqual([
      15, 0, 0,
    ]);
    expect(changes(nudgeAction(selecting({ kind: 'light', id: 'panel' }), { mode: 'scale', direction: 'up', big: false }, fromFront))?.size).toEqual([
      1.1, 2.2,
    ]);
  });

  it('moves the camera with its target, so only the view changes', () => {
    const action = nudgeAction(selecting({ kind: 'camera' }), { mode: 'translate', direction: 'right', big: false }, fromFront);
    expect(action?.type).toBe('camera.changed');
    expect(changes(action)?.position).toEqual([0.1, 1.5, 5]);
    expect((changes(action)?.target as number[]).map((v) => Math.round(v * 1000) / 1000)).toEqual([0.1, 0.5, 0]);
  });

  it('gives the store an ordinary change it accepts, and nothing without a selection', () => {
    const state = selecting({ kind: 'object', id: 'box' });
    const after = reduce(state, nudgeAction(state, { mode: 'translate', direction: 'up', big: false }, fromFront)!);
    expect(after.error).toBeUndefined();
    expect(after.state.scene.objects[0]!.position).toEqual([0.9, 0.5, -0.5]);
    expect(nudgeAction(selecting(null), { mode: 'translate', direction: 'up', big: false }, fromFront)).toBeNull();
  });

  it('reads the viewer’s axes from the 3D view’s camera, and says the step and the Shift step', () => {
    const camera = new PerspectiveCamera();
    camera.position.set(0, 0, 5);
    camera.lookAt(0, 0, 0);
    const axes = viewAxesOf(camera);
    expect(axes.right.map((v) => Math.round(v) + 0)).toEqual([1, 0, 0]);
    expect(axes.forward.map((v) => Math.round(v) + 0)).toEqual([0, 0, -1]);
    expect(nudgeNote('Ball', 'translate', false)).toBe('Ball moved 0.1 m. With Shift: 0.5 m.');
    expect(nudgeNote('Box', 'rotate', true)).toBe('Box turned 15°. Without Shift: 5°.');
  });
});
