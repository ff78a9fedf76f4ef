import { issueLine } from '../../src/util/issue.ts';
import { type BufferGeometry, type Mesh, type MeshPhongMaterial, Vector3 } from 'three';
import { describe, expect, it } from 'vitest';
import { type LabAction } from '../../src/lab-state/lab-action.ts';
import { reduce } from '../../src/lab-state/lab-reducer.ts';
import { type LabState, initialState } from '../../src/lab-state/lab-state.ts';
import type { MeshData, MeshLibrary } from '../../src/scene/mesh-data.ts';
import { defaultScene } from '../../src/scene/scene-defaults.ts';
import { TRANSPARENT_OPACITY } from '../../src/view/raster-material.ts';
import { type MeshLoader, SceneSync } from '../../src/view/scene-sync.ts';

const TRIANGLE: MeshData = { positions: new Float32Array([0, 0, 0, 1, 0, 0, 0, 1, 0]), normals: null, indices: new Uint32Array([0, 1, 2]) };

function apply(state: LabState, ...actions: LabAction[]): LabState {
  for (const action of actions) {
    const { state: next, error } = reduce(state, action);
    if (error) throw new Error(error.map(issueLine).join('\n'));
    state = next;
  }
  return state;
}

function meshOf(sync: SceneSync, id: string): Mesh<BufferGeometry, MeshPhongMaterial> {
  return sync.objectOf(id) as Mesh<BufferGeometry, MeshPhongMaterial>;
}

const noModels: MeshLoader = () => Promise.resolve(new Map());

describe('scene sync', () => {
  it('draws every object as its unit shape, placed, turned and scaled like the tracer does', () => {
    const sync = new SceneSync(noModels, () => {});
    const state = initialState(defaultScene());
    sync.sync(state.scene);
    expect(sync.group.children.map((child) => child.name)).toEqual(state.scene.objects.map((o) => o.id));
    const box = meshOf(sync, 'box');
    expect(box.position.toArray()).toEqual([-0.8, 0.35, -2.4]);
    expect(box.rotation.y).toBeCloseTo((30 * Math.PI) / 180, 12);
    expect(box.scale.toArray()).toEqual([0.7, 0.7, 0.7]);
    box.geometry.computeBoundingBox();
    expect(box.geometry.boundingBox!.max.toArray()).toEqual([0.5, 0.5, 0.5]);
    const floor = meshOf(sync, 'floor');
    // The unit plane lies in XZ and faces +Y.
    const normal = new Vector3().fromBufferAttribute(floor.geometry.getAttribute('normal'), 0);
    expect(normal.distanceTo(new Vector3(0, 1, 0))).toBeLessThan(1e-12);
    meshOf(sync, 'red-ball').geometry.computeBoundingSphere();
    expect(meshOf(sync, 'red-ball').geometry.boundingSphere!.radius).toBeCloseTo(0.5, 6);
  });

  it('shares one geometry per shape and edits a dragged slider in place: no new geometry or material', () => {
    const sync = new SceneSync(noModels, () => {});
    let state = initialState(defaultScene());
    sync.sync(state.scene);
    const before = new Map(
      state.scene.objects.map((o) => [o.id, { geometry: meshOf(sync, o.id).geometry, material: meshOf(sync, o.id).material, mesh: meshOf(sync, o.id) }]),
    );
    expect(meshOf(sync, 'red-ball').geometry).toBe(meshOf(sync, 'mirror-ball').geometry);
    for (const diffuse of [0.2, 0.4, 0.6, 0.8]) {
      state = apply(state, { type: 'material.changed', id: 'red-ball', changes: { diffuse } });
      sync.sync(state.scene);
    }
    for (const [id, was] of before) {
      expect(meshOf(sync, id)).toBe(was.mesh);
      expect(meshOf(sync, id).geometry).toBe(was.geometry);
      expect(meshOf(sync, id).material).toBe(was.material);
    }
    // kd·C: the red ball's diffuse colour followed the slider.
    expect(meshOf(sync, 'red-ball').material.color.r).toBeCloseTo(0.9 * 0.8, 6);
  });

  it('gives the Phong terms: kd·C diffuse, untinted ks specular, n shininess, C·(ka + Σ la·Lc) emissive', () => {
    const sync = new SceneSync(noModels, () => {});
    const state = initialState(defaultScene());
    sync.sync(state.scene);
    const ball = state.scene.objects.find((o) => o.id === 'mirror-ball')!;
    const material = meshOf(sync, 'mirror-ball').material;
    const ambientLights = state.scene.lights.reduce((sum, light) => sum + light.ambient * light.color[0], 0);
    expect(material.color.r).toBeCloseTo(ball.material.color[0] * ball.material.diffuse, 6);
    expect(material.specular.toArray()).toEqual([0.85, 0.85, 0.85]);
    expect(material.shininess).toBe(200);
    expect(material.emissive.r).toBeCloseTo(ball.material.color[0] * (ball.material.ambient + ambientLights), 6);
  });

  it('shows glass see-through and recompiles only when transparency switches', () => {
    const sync = new SceneSync(noModels, () => {});
    let state = initialState(defaultScene());
    sync.sync(state.scene);
    const glass = meshOf(sync, 'glass-ball').material;
    expect([glass.transparent, glass.opacity, glass.depthWrite]).toEqual([true, TRANSPARENT_OPACITY, false]);
    const version = glass.version;
    state = apply(state, { type: 'material.changed', id: 'glass-ball', changes: { specular: 0.3 } });
    sync.sync(state.scene);
    expect(glass.version).toBe(version);
    state = apply(state, { type: 'material.changed', id: 'glass-ball', changes: { transparent: false } });
    sync.sync(state.scene);
    expect([glass.transparent, glass.opacity]).toEqual([false, 1]);
    expect(glass.version).toBeGreaterThan(version);
  });

  it('moves objects when the store does, adds new ones and disposes the material of deleted ones', () => {
    const sync = new SceneSync(noModels, () => {});
    let state = initialState(defaultScene());
    sync.sync(state.scene);
    const ballMaterial = meshOf(sync, 'red-ball').material;
    let disposed = false;
    ballMaterial.addEventListener('dispose', () => (disposed = true));
    state = apply(
      state,
      { type: 'object.changed', id: 'box', changes: { position: [1, 2, 3] } },
      { type: 'object.deleted', id: 'red-ball' },
      { type: 'object.added', shape: 'cylinder' },
    );
    sync.sync(state.scene);
    expect(meshOf(sync, 'box').position.toArray()).toEqual([1, 2, 3]);
    expect(sync.objectOf('red-ball')).toBeUndefined();
    expect(disposed).toBe(true);
    expect(sync.group.children).toHaveLength(5);
    expect(meshOf(sync, 'cylinder-1').geometry.type).toBe('CylinderGeometry');
  });

  it('downloads a model once, shows it on every object using it, and frees it when the last one goes', async () => {
    const requests: string[][] = [];
    let changes = 0;
    const loader: MeshLoader = async (names) => {
      requests.push([...names]);
      return new Map([[[...names][0]!, TRIANGLE]]) as MeshLibrary;
    };
    const sync = new SceneSync(loader, () => changes++);
    let state = apply(
      initialState(defaultScene()),
      { type: 'object.added', shape: 'mesh', mesh: 'prism' },
      { type: 'object.added', shape: 'mesh', mesh: 'prism' },
    );
    sync.sync(state.scene);
    expect(meshOf(sync, 'mesh-1').geometry.getAttribute('position')).toBeUndefined();
    await Promise.resolve();
    await Promise.resolve();
    expect(requests).toEqual([['prism']]);
    expect(changes).toBe(1);
    const model = meshOf(sync, 'mesh-1').geometry;
    expect(meshOf(sync, 'mesh-2').geometry).toBe(model);
    // A flat-shaded model gets face normals: the triangle in z = 0 faces +z.
    expect(Array.from(model.getAttribute('normal').array.slice(0, 3))).toEqual([0, 0, 1]);
    let freed = false;
    model.addEventListener('dispose', () => (freed = true));
    state = apply(state, { type: 'object.deleted', id: 'mesh-1' });
    sync.sync(state.scene);
    expect(freed).toBe(false);
    state = apply(state, { type: 'object.deleted', id: 'mesh-2' });
    sync.sync(state.scene);
    expect(freed).toBe(true);
  });

  it('reports a model that cannot be loaded, and tries again next time', async () => {
    const messages: (string | undefined)[] = [];
    let calls = 0;
    const sync = new SceneSync(
      async () => {
        calls++;
        throw new Error('mesh "prism": downloading failed (HTTP 404)');
      },
      (error) => messages.push(error),
    );
    let state = apply(initialState(defaultScene()), { type: 'object.added', shape: 'mesh', mesh: 'prism' });
    sync.sync(state.scene);
    await new Promise((resolve) => setTimeout(resolve, 0));
    expect(messages).toEqual(['mesh "prism": downloading failed (HTTP 404)']);
    state = apply(state, { type: 'object.changed', id: 'mesh-1', changes: { mesh: 'capsule' } });
    sync.sync(state.scene);
    state = apply(state, { type: 'object.changed', id: 'mesh-1', changes: { mesh: 'prism' } });
    sync.sync(state.scene);
    expect(calls).toBe(3);
  });
});
