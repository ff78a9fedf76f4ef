import { issueLine } from '../../src/util/issue.ts';
import { beforeAll, describe, expect, it } from 'vitest';
import { reduce } from '../../src/lab-state/lab-reducer.ts';
import { type LabState, initialState } from '../../src/lab-state/lab-state.ts';
import { labActionSchema } from '../../src/quest/lab-action-schema.ts';
import { loadMeshesFromDisk } from '../../src/scene/load-meshes-node.ts';
import type { MeshLibrary } from '../../src/scene/mesh-data.ts';
import { parseScene } from '../../src/scene/scene-schema.ts';
import { buildTracerScene } from '../../src/tracer/tracer-scene.ts';
import { countPixelTests } from '../../src/tracer/triangle-test-count.ts';
import { BvhBoxes } from '../../src/view/bvh-boxes.ts';

let meshes: MeshLibrary;
beforeAll(async () => {
  meshes = await loadMeshesFromDisk(['character', 'capsule']);
});

function labState(camera: object = {}): LabState {
  const parsed = parseScene({
    version: 1,
    camera,
    objects: [
      { id: 'ball', shape: 'sphere' },
      { id: 'hero', shape: 'mesh', mesh: 'character', position: [0, 0.9, 0] },
      { id: 'pill', shape: 'mesh', mesh: 'capsule', position: [2, 0.5, 0] },
    ],
  });
  if (!parsed.ok) throw new Error(parsed.errors.map(issueLine).join('\n'));
  return initialState(parsed.scene);
}

describe('the BVH view options in the app state', () => {
  it('start hidden at depth 2, and change by bvh.changed', () => {
    const start = labState();
    expect(start.bvh).toEqual({ show: false, depth: 2, showBounds: false });
    const { state, error } = reduce(start, { type: 'bvh.changed', changes: { show: true, depth: 5 } });
    expect(error).toBeUndefined();
    expect(state.bvh).toEqual({ show: true, depth: 5, showBounds: false });
  });

  it('go back to their defaults when a scene is loaded (a level opens): boxes belong to their scene', () => {
    const shown = reduce(labState(), { type: 'bvh.changed', changes: { show: true, showBounds: true, depth: 7 } }).state;
    expect(reduce(shown, { type: 'scene.loaded', scene: shown.scene }).state.bvh).toEqual({ show: false, depth: 2, showBounds: false });
  });

  it('refuse a depth outside 0–20 or not whole, keeping the state', () => {
    const start = labState();
    for (const depth of [-1, 21, 2.5, Number.NaN]) {
      const { state, error } = reduce(start, { type: 'bvh.changed', changes: { depth } });
      expect(error?.map(issueLine)).toEqual([expect.stringMatching(/^bvh\.depth: must be a whole number from 0 to 20/)]);
      expect(state).toBe(start);
    }
  });

  it('are checked in level files: unknown fields and wrong types are refused', () => {
    expect(labActionSchema.safeParse({ type: 'bvh.changed', changes: { showBounds: true } }).success).toBe(true);
    const wrong = labActionSchema.safeParse({ type: 'bvh.changed', changes: { depth: 'deep', colour: 1 } });
    expect(wrong.success).toBe(false);
    expect(wrong.error?.issues.map((issue) => issue.message)).toEqual([
      'depth must be a number, got "deep"',
      expect.stringMatching(/^unknown field "colour" \(known: /),
    ]);
  });
});

describe('the boxes drawn in the view', () => {
  const drawn = (boxes: BvhBoxes) =>
    Object.fromEntries(
      boxes.object.children.map((child) => [
        child.name,
        (child as unknown as { geometry: { getAttribute(n: string): { count: number } } }).geometry.getAttribute('position').count / 24,
      ]),
    );

  async function boxesFor(state: LabState): Promise<BvhBoxes> {
    let changed = 0;
    const boxes = new BvhBoxes(
      () => changed++,
      async () => meshes,
    );
    boxes.update(state);
    await expect.poll(() => changed).toBe(1);
    return boxes;
  }

  it('draw every model’s BVH down to the depth (ancestors included) when no model is selected', async () => {
    const state = reduce(labState(), { type: 'bvh.changed', changes: { show: true, depth: 2 } }).state;
    expect(drawn(await boxesFor(state))).toEqual({ 'bvh:hero': 7, 'bvh:pill': 7 });
  });

  it('draw only the selected model’s BVH, and every object’s bounding box', async () => {
    let state = reduce(labState(), { type: 'bvh.changed', changes: { show: true, depth: 0, showBounds: true } }).state;
    state = reduce(state, { type: 'selection.changed', selection: { kind: 'object', id: 'pill' } }).state;
    expect(drawn(await boxesFor(state))).toEqual({ 'bvh:pill': 1, bounds: 3 });
  });

  it('with a pixel selected, draw the boxes its ray entered (solid green) and missed (dashed red) over a dimmed tree', async () => {
    // Close up on the character, so that several pixels show it.
    let state = reduce(labState({ position: [0, 0.9, 1.5], target: [0, 0.9, 0] }), { type: 'bvh.changed', changes: { show: true, depth: 1 } }).state;
    const traced = buildTracerScene(state.scene, meshes);
    const [columns, rows] = state.scene.camera.pixels;
    const pixels = Array.from({ length: columns * rows }, (_, i) => [i % columns, Math.floor(i / columns)] as const);
    const pixel = pixels.find((p) => countPixelTests(traced, meshes, p).hitId === 'hero')!;
    expect(pixel).toBeDefined();
    state = reduce(state, { type: 'pixel.selected', pixel: [...pixel] }).state;
    const boxes = await boxesFor(state);
    const visits = countPixelTests(traced, meshes, pixel).objects.find((o) => o.id === 'hero')!.mesh!.visits;
    const entered = visits.filter((v) => v.entered).length;
    expect(entered).toBeGreaterThan(0);
    expect(entered).toBeLessThan(visits.length);
    expect(drawn(boxes)).toEqual({ 'bvh:hero': 3, 'bvh:pill': 3, 'bvh-ray-entered:hero': entered, 'bvh-ray-missed:hero': visits.length - entered });
    const material = (name: string) => (boxes.object.getObjectByName(name) as unknown as { material: { type: string } }).material.type;
    expect(material('bvh-ray-entered:hero')).toBe('LineBasicMaterial');
    expect(material('bvh-ray-missed:hero')).toBe('LineDashedMaterial');
    // The tree steps back: every one of its boxes is faint.
    const tree = (
      boxes.object.getObjectByName('bvh:hero') as unknown as { geometry: { getAttribute(n: string): { array: ArrayLike<number> } } }
    ).geometry.getAttribute('color').array;
    expect(Math.max(...Array.from(tree).filter((_, i) => i % 4 === 3))).toBeLessThan(0.5);
  });

  it('draw nothing when both are off, and keep the newest state when models load late', async () => {
    const on = reduce(labState(), { type: 'bvh.changed', changes: { show: true } }).state;
    let release: (library: MeshLibrary) => void = () => {};
    const boxes = new BvhBoxes(
      () => {},
      () => new Promise((resolve) => (release = resolve)),
    );
    boxes.update(on);
    boxes.update(labState());
    release(meshes);
    await new Promise((resolve) => setTimeout(resolve, 0));
    expect(boxes.object.children).toHaveLength(0);
  });
});
