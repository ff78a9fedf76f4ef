import { describe, expect, it } from 'vitest';
import { RenderPool } from '../../src/render/render-pool.ts';
import { loadMeshesFromDisk } from '../../src/scene/load-meshes-node.ts';
import { createRenderHandler } from '../../workers/render-core.ts';
import type { RenderRequest } from '../../workers/protocol.ts';
import { matte, sceneFrom } from '../support/test-scene.ts';

describe('models in the render pool', () => {
  it('are sent to a worker once; later scenes reuse them (and their BVHs)', async () => {
    const posted: RenderRequest[] = [];
    // An in-process "worker": the real message handler, no thread.
    const pool = new RenderPool({
      size: 1,
      createWorker: ({ onResponse }) => {
        const handle = createRenderHandler((response) => onResponse(response));
        return { post: (request) => (posted.push(request), handle(request)), terminate: () => {} };
      },
    });
    const meshes = await loadMeshesFromDisk(['capsule']);
    const scene = (x: number) => sceneFrom({ objects: [{ id: 'pill', shape: 'mesh', mesh: 'capsule', position: [x, 0, 0], material: matte([1, 1, 1]) }] });
    pool.setScene(scene(0), meshes);
    await pool.ready();
    pool.setScene(scene(0.5), meshes);
    await pool.ready();
    const loads = posted.filter((request) => request.type === 'load-scene');
    expect(loads.map((load) => [...load.meshes.keys()])).toEqual([['capsule'], []]);
    const trace = await pool.tracePixel(4, 3);
    expect(trace.rays[0].objectId).toBe('pill');
    pool.dispose();
  });
});
