import { describe, expect, it } from 'vitest';
import { issueLine } from '../../src/util/issue.ts';
import type { LabAction } from '../../src/lab-state/lab-action.ts';
import { Store } from '../../src/lab-state/store.ts';
import { DEFAULT_GIZMO, DEFAULT_RAY_VIEW, initialState } from '../../src/lab-state/lab-state.ts';
import { defaultScene } from '../../src/scene/scene-defaults.ts';

const newStore = () => new Store(initialState(defaultScene()));

describe('the store and its named actions', () => {
  it('applies a valid change and tells listeners which action did it', () => {
    const store = newStore();
    const seen: string[] = [];
    store.subscribe((_, action) => seen.push(action.type));
    expect(store.dispatch({ type: 'material.changed', id: 'red-ball', changes: { color: [0, 1, 0] } })).toBeUndefined();
    expect(store.state.scene.objects.find((o) => o.id === 'red-ball')!.material.color).toEqual([0, 1, 0]);
    expect(seen).toEqual(['material.changed']);
  });

  it('counts accepted scene changes, not refused ones or view-only ones', () => {
    const store = newStore();
    expect(store.sceneRevision).toBe(0);
    store.dispatch({ type: 'material.changed', id: 'red-ball', changes: { color: [0, 1, 0] } });
    expect(store.sceneRevision).toBe(1);
    store.dispatch({ type: 'settings.changed', changes: { supersampling: 40 } });
    store.dispatch({ type: 'selection.changed', selection: { kind: 'camera' } });
    expect(store.sceneRevision).toBe(1);
    // A change back is still a change: the scene on show was made from another revision.
    store.dispatch({ type: 'material.changed', id: 'red-ball', changes: { color: [1, 0, 0] } });
    expect(store.sceneRevision).toBe(2);
  });

  it("keeps the scene as it is for a change to the values it has (a slider's commit after its last input)", () => {
    const store = newStore();
    const seen: string[] = [];
    store.subscribe((_, action) => seen.push(action.type));
    store.dispatch({ type: 'material.changed', id: 'red-ball', changes: { shininess: 80 } });
    const changed = store.state;
    const same: LabAction[] = [
      { type: 'material.changed', id: 'red-ball', changes: { shininess: 80 } },
      { type: 'object.changed', id: 'red-ball', changes: { position: [...changed.scene.objects.find((o) => o.id === 'red-ball')!.position] } },
      { type: 'camera.changed', changes: { pixels: [...changed.scene.camera.pixels] } },
      { type: 'settings.changed', changes: { supersampling: changed.scene.settings.supersampling } },
      { type: 'light.changed', id: changed.scene.lights[0].id, changes: { intensity: changed.scene.lights[0].intensity } },
    ];
    for (const action of same) expect(store.dispatch(action), action.type).toBeUndefined();
    expect(store.state).toBe(changed);
    expect(store.sceneRevision).toBe(1);
    // The listeners still hear every action (the timing log records the commit).
    expect(seen).toEqual(['material.changed', ...same.map((action) => action.type)]);
    // A value that differs in one element of a list is a change.
    const [x, y, z] = changed.scene.objects.find((o) => o.id === 'red-ball')!.position;
    store.dispatch({ type: 'object.changed', id: 'red-ball', changes: { position: [x, y, z + 0.5] } });
    expect(store.sceneRevision).toBe(2);
  });

  it('a loaded scene starts with a clean view: ray filters and gizmo mode reset, the colour palette kept', () => {
    const store = newStore();
    store.dispatch({ type: 'rays.changed', changes: { hideNoHit: true, negligibleThreshold: 0.1, transparency: 0.6, colorBlindPalette: true } });
    store.dispatch({ type: 'gizmo.changed', changes: { mode: 'rotate', snap: true } });
    store.dispatch({ type: 'scene.loaded', scene: defaultScene() });
    expect(store.state.rays).toEqual({ ...DEFAULT_RAY_VIEW, colorBlindPalette: true });
    expect(store.state.gizmo).toEqual(DEFAULT_GIZMO);
  });

  it('refuses an out-of-range value with the schema message and loses nothing', () => {
    const store = newStore();
    const before = store.state;
    const error = store.dispatch({ type: 'settings.changed', changes: { supersampling: 40 } });
    expect(error?.map(issueLine)).toEqual(['settings.supersampling: must be between 1 and 8, got 40']);
    expect(store.state).toBe(before);
    expect(store.dispatch({ type: 'material.changed', id: 'nope', changes: { ambient: 0.5 } })?.map(issueLine)).toEqual(['objects: there is no object "nope"']);
  });

  it("changing a light type keeps its place and colour and takes the new type's defaults", () => {
    const store = newStore();
    store.dispatch({ type: 'light.changed', id: 'lamp', changes: { type: 'area' } });
    const lamp = store.state.scene.lights.find((l) => l.id === 'lamp')!;
    expect(lamp.type).toBe('area');
    expect(lamp.position).toEqual([2, 4, 3]);
    expect(lamp.type === 'area' && lamp.samples).toBe(3);
  });

  it('a spot or area light can become a point light (it drops its rotation)', () => {
    const store = newStore();
    expect(store.dispatch({ type: 'light.changed', id: 'spot', changes: { type: 'point' } })).toBeUndefined();
    const spot = store.state.scene.lights.find((l) => l.id === 'spot')!;
    expect(spot.type).toBe('point');
    expect('rotation' in spot).toBe(false);
  });

  it('an action that makes the reducer throw is refused with a message, never thrown', () => {
    const store = newStore();
    const before = store.state;
    const bogus = { type: 'light.changed', id: 'spot', changes: { type: 'laser' } } as unknown as Parameters<Store['dispatch']>[0];
    expect(store.dispatch(bogus)?.map(issueLine)).toEqual([expect.stringMatching(/^light\.changed: /)]);
    expect(store.state).toBe(before);
  });

  it('selects only pixels on the screen, and forgets one the screen shrinks away from', () => {
    const store = newStore();
    expect(store.dispatch({ type: 'pixel.selected', pixel: [8, 0] })?.map(issueLine)).toEqual(['pixel: must be inside the 8×6 screen, got 8,0']);
    store.dispatch({ type: 'pixel.selected', pixel: [7, 5] });
    expect(store.state.selectedPixel).toEqual([7, 5]);
    store.dispatch({ type: 'camera.changed', changes: { pixels: [4, 4] } });
    expect(store.state.selectedPixel).toBeNull();
  });

  it('adds objects and lights with fresh ids, selects them, and deselects what is deleted', () => {
    const store = newStore();
    store.dispatch({ type: 'object.added', shape: 'cylinder' });
    expect(store.state.selection).toEqual({ kind: 'object', id: 'cylinder-1' });
    store.dispatch({ type: 'object.deleted', id: 'cylinder-1' });
    expect(store.state.selection).toBeNull();
    expect(store.state.scene.objects.some((o) => o.id === 'cylinder-1')).toBe(false);
    store.dispatch({ type: 'light.added', lightType: 'spot' });
    expect(store.state.selection).toEqual({ kind: 'light', id: 'spot-1' });
  });

  it('facts from the view change nothing but still reach listeners', () => {
    const store = newStore();
    const before = store.state;
    let heard = '';
    store.subscribe((_, action) => (heard = action.type));
    store.dispatch({ type: 'view.orbited' });
    expect(store.state).toBe(before);
    expect(heard).toBe('view.orbited');
  });
});
