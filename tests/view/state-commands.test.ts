import { describe, expect, it } from 'vitest';
import { initialState, type LabState } from '../../src/lab-state/lab-state.ts';
import { defaultScene } from '../../src/scene/scene-defaults.ts';
import { nextSelection, stateCommand } from '../../src/view/state-commands.ts';

const base = initialState(defaultScene());
const selecting = (selection: LabState['selection']): LabState => ({ ...base, selection });
const firstObject = base.scene.objects[0]!.id;
const firstLight = base.scene.lights[0]!.id;

describe('view commands that change the lab state', () => {
  it('deletes the selected object or light, and explains when nothing can be deleted', () => {
    expect(stateCommand({ kind: 'delete' }, selecting({ kind: 'object', id: firstObject }))).toEqual({ action: { type: 'object.deleted', id: firstObject } });
    expect(stateCommand({ kind: 'delete' }, selecting({ kind: 'light', id: firstLight }))).toEqual({ action: { type: 'light.deleted', id: firstLight } });
    expect(stateCommand({ kind: 'delete' }, selecting({ kind: 'camera' }))).toEqual({ message: "The ray tracer's camera cannot be deleted." });
    expect(stateCommand({ kind: 'delete' }, selecting(null))?.action).toBeUndefined();
  });

  it('toggles the gizmo options against the current ones', () => {
    expect(stateCommand({ kind: 'toggle-space' }, base)).toEqual({ action: { type: 'gizmo.changed', changes: { space: 'local' } } });
    expect(stateCommand({ kind: 'toggle-snap' }, { ...base, gizmo: { ...base.gizmo, snap: true } })).toEqual({ action: { type: 'gizmo.changed', changes: { snap: false } } });
  });

  it('sets a gizmo mode, with a note when the selection cannot be changed that way', () => {
    expect(stateCommand({ kind: 'gizmo-mode', mode: 'rotate' }, selecting({ kind: 'object', id: firstObject }))).toEqual({ action: { type: 'gizmo.changed', changes: { mode: 'rotate' } } });
    const camera = stateCommand({ kind: 'gizmo-mode', mode: 'scale' }, selecting({ kind: 'camera' }));
    expect(camera?.action).toEqual({ type: 'gizmo.changed', changes: { mode: 'scale' } });
    expect(camera?.message).toMatch(/cannot be changed that way/);
  });

  it('Escape deselects, and does nothing to the state without a selection', () => {
    expect(stateCommand({ kind: 'escape' }, selecting({ kind: 'camera' }))).toEqual({ action: { type: 'selection.changed', selection: null } });
    expect(stateCommand({ kind: 'escape' }, base)).toEqual({});
  });

  it('leaves camera moves to the view', () => {
    for (const command of [{ kind: 'orbit', dxDeg: 5, dyDeg: 0 }, { kind: 'zoom', factor: 2 }, { kind: 'fly' }, { kind: 'help' }] as const) {
      expect(stateCommand(command, base)).toBeNull();
    }
  });

  it('steps through objects, lights and the camera, round', () => {
    const { objects, lights } = base.scene;
    expect(nextSelection(base, 1)).toEqual({ kind: 'object', id: objects[0]!.id });
    expect(nextSelection(base, -1)).toEqual({ kind: 'camera' });
    expect(nextSelection(selecting({ kind: 'object', id: objects.at(-1)!.id }), 1)).toEqual({ kind: 'light', id: lights[0]!.id });
    expect(nextSelection(selecting({ kind: 'camera' }), 1)).toEqual({ kind: 'object', id: objects[0]!.id });
  });
});
