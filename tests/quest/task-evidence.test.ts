import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { initialState } from '../../src/lab-state/lab-state.ts';
import { Store } from '../../src/lab-state/store.ts';
import { loadLevels } from '../../src/quest/level-index.ts';
import { DEFAULT_SEED } from '../../src/render/render-job.ts';
import { loadMeshesFromDisk } from '../../src/scene/load-meshes-node.ts';
import { meshNamesInScene } from '../../src/scene/mesh-names.ts';
import { followRayPath } from '../../src/tracer/ray-path.ts';
import { tracePixel } from '../../src/tracer/trace-pixel.ts';
import { buildTracerScene } from '../../src/tracer/tracer-scene.ts';

/**
 * The rays a task's text names (its `evidence`, docs/levels.md) are rays the tracer casts:
 * replaying every level's required solutions in order, each named ray is in its pixel's tree
 * for the scene as it is when the task comes up. The browser test (e2e/guide-targets.spec.ts)
 * checks that they show on screen; this catches, in every run, a scene edited under a text
 * ("a green ray comes out at the back" with no such ray).
 */

const levelsFolder = new URL('../../levels/', import.meta.url);
const catalog = loadLevels(readFileSync(new URL('index.json', levelsFolder), 'utf8'), (name) => readFileSync(new URL(name, levelsFolder), 'utf8'));
const levels = catalog.chapters.flatMap((chapter) => chapter.entries.flatMap((entry) => (entry.ok ? [entry.level] : [])));
const withRays = levels.filter((level) => level.tasks.some((task) => task.evidence?.rays));

describe('the rays a task names are traced', () => {
  it('the levels with rays name them as evidence: 2 to 10, 12, 14, 16, 18 to 20', () => {
    expect(withRays.map((level) => Number.parseInt(level.id, 10)).sort((a, b) => a - b)).toEqual([2, 3, 4, 5, 6, 7, 8, 9, 10, 12, 14, 16, 18, 19, 20]);
  });

  for (const level of withRays) {
    it(`${level.id}: every named ray is in its pixel's tree when its task comes up`, async () => {
      const store = new Store(initialState(level.scene));
      const missing: string[] = [];
      for (const task of level.tasks) {
        const rays = task.evidence?.rays;
        if (rays) {
          const { scene } = store.state;
          const tracer = buildTracerScene(scene, await loadMeshesFromDisk(meshNamesInScene(scene)));
          const trace = tracePixel(tracer, rays.pixel[0], rays.pixel[1], DEFAULT_SEED);
          for (const path of rays.paths) if (!followRayPath(trace, path)) missing.push(`${task.id}: pixel ${rays.pixel} has no ray "${path}"`);
        }
        // The way every learner goes: the required tasks' solutions (an optional one may be left out).
        if (task.mandatory) for (const action of task.solution ?? []) expect(store.dispatch(action), `${task.id}: ${action.type}`).toBeUndefined();
      }
      expect(missing).toEqual([]);
    });
  }
});
