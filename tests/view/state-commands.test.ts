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
    expect(stateCommand({ kind: 'toggle-snap' }, { ...base, gizmo: { ...base.gizmo, snap: true } })).toEqual({
      action: { type: 'gizmo.changed', changes: { snap: false } },
    });
  });

  it('sets a gizmo mode, with a note when the selection cannot be changed that way', () => {
    expect(stateCommand({ kind: 'gizmo-mode', mode: 'rotate' }, selecting({ kind: 'object', id: firstObject }))).toEqual({
      action: { type: 'gizmo.changed', changes: { mode: 'rotate' } },
    });
    const camera = stateCommand({ kind: 'gizmo-mode', mode: 'scale' }, selecting({ kind: 'camera' }));
    expect(camera?.action).toEqual({ type: 'gizmo.changed', changes: { mode: 'scale' } });
    expect(camera?.message).toMatch(/cannot be changed that way/);
  });

  it('Escape deselects, then shows every pixel again, and does nothing to the state when neither is chosen', () => {
    expect(stateCommand({ kind: 'escape' }, { ...selecting({ kind: 'camera' }), selectedPixel: [1, 1] })).toEqual({
      action: { type: 'selection.changed', selection: null },
    });
    expect(stateCommand({ kind: 'escape' }, { ...base, selectedPixel: [1, 1] })).toEqual({ action: { type: 'pixel.deselected' } });
    expect(stateCommand({ kind: 'escape' }, base)).toEqual({});
  });

  it('chooses a pixel of the camera’s screen with P (the top left first) and the arrows, kept on the screen', () => {
    const [columns, rows] = base.scene.camera.pixels;
    const chosen = stateCommand({ kind: 'toggle-pixel' }, base);
    expect(chosen?.action).toEqual({ type: 'pixel.selected', pixel: [0, 0] });
    expect(chosen?.note).toMatch(/Pixel 0, 0/);
    expect(stateCommand({ kind: 'toggle-pixel' }, { ...base, selectedPixel: [2, 1] })?.action).toEqual({ type: 'pixel.deselected' });
    expect(stateCommand({ kind: 'pixel-step', dx: 1, dy: 0 }, { ...base, selectedPixel: [2, 1] })?.action).toEqual({ type: 'pixel.selected', pixel: [3, 1] });
    expect(stateCommand({ kind: 'pixel-step', dx: 0, dy: -1 }, { ...base, selectedPixel: [2, 1] })?.action).toEqual({ type: 'pixel.selected', pixel: [2, 0] });
    // At the edge nothing changes (no event that a goal could count twice).
    expect(stateCommand({ kind: 'pixel-step', dx: 1, dy: 0 }, { ...base, selectedPixel: [columns - 1, 0] })).toEqual({});
    expect(stateCommand({ kind: 'pixel-step', dx: 0, dy: 1 }, { ...base, selectedPixel: [0, rows - 1] })).toEqual({});
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
