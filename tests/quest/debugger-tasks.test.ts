import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { findStep, findTerm } from '../../src/debugger/debug-goals.ts';
import { debugProgram } from '../../src/debugger/debug-steps.ts';
import { initialState } from '../../src/lab-state/lab-state.ts';
import { Store } from '../../src/lab-state/store.ts';
import { loadLevels } from '../../src/quest/level-index.ts';
import { loadMeshesFromDisk } from '../../src/scene/load-meshes-node.ts';
import { meshNamesInScene } from '../../src/scene/mesh-names.ts';
import { DEFAULT_SEED } from '../../src/render/render-job.ts';
import { tracePixel } from '../../src/tracer/trace-pixel.ts';
import { buildTracerScene } from '../../src/tracer/tracer-scene.ts';

/**
 * The headless solver (levels-solvable.test.ts) dispatches a solution's debugger actions as
 * they are written. This proves each one is what the real debugger reports: replaying every
 * level's solutions in order, each `debugger.stepped` is the step the debugger reaches on
 * the selected pixel of the scene at that moment (same index, same count, same ray), and
 * each `debugger.term-clicked` names a term of one of that pixel's hits that has a ray.
 */

const levelsFolder = new URL('../../levels/', import.meta.url);
const catalog = loadLevels(readFileSync(new URL('index.json', levelsFolder), 'utf8'), (name) => readFileSync(new URL(name, levelsFolder), 'utf8'));
const levels = catalog.chapters.flatMap((chapter) => chapter.entries.flatMap((entry) => (entry.ok ? [entry.level] : [])));
const withDebugger = levels.filter((level) => level.tasks.some((task) => task.solution?.some((action) => action.type.startsWith('debugger.'))));

describe('the ray debugger in every level with rays (issue 37)', () => {
  it('every level shows it, or says in its file why it is left out', () => {
    for (const level of levels) {
      const hidden = level.ui.hidden?.debugger;
      expect(level.ui.panels.includes('debugger') || hidden !== undefined, `${level.id} neither shows the debugger nor says why not`).toBe(true);
      if (hidden !== undefined) expect(typeof hidden === 'string' ? hidden : hidden.en, `${level.id}: the reason`).toMatch(/\w{3,}.*\w{3,}/);
    }
    expect(levels.filter((level) => level.ui.hidden?.debugger).map((level) => level.id)).toEqual(['01-introduction']);
  });
});

describe('the levels’ debugger solutions are reachable in the debugger', () => {
  it('the shading, shadows, reflections, refraction and attenuation levels have debugger tasks', () => {
    expect(withDebugger.map((level) => level.id)).toEqual(['03-shading', '04-shadows', '05-reflections', '06-refraction', '09-attenuation']);
  });

  for (const level of withDebugger) {
    it(`${level.id}: each debugger action is one the debugger reports for the selected pixel`, async () => {
      expect(level.ui.panels).toContain('debugger');
      const store = new Store(initialState(level.scene));
      let checked = 0;
      for (const task of level.tasks) {
        for (const action of task.solution ?? []) {
          if (action.type === 'debugger.stepped' || action.type === 'debugger.term-clicked') {
            const { scene, selectedPixel } = store.state;
            if (!selectedPixel) throw new Error(`task "${task.id}": a debugger action with no pixel selected`);
            const tracer = buildTracerScene(scene, await loadMeshesFromDisk(meshNamesInScene(scene)));
            const program = debugProgram(tracePixel(tracer, selectedPixel[0], selectedPixel[1], DEFAULT_SEED, { terms: true }), scene);
            if (action.type === 'debugger.stepped') {
              expect(action.of, `task "${task.id}": steps of pixel ${selectedPixel}`).toBe(program.steps.length);
              expect(action.ray && findStep(program, action.ray), `task "${task.id}": the step of ${JSON.stringify(action.ray)}`).toBe(action.step);
            } else {
              expect(findTerm(program, scene, action.term, action.lightId), `task "${task.id}": a ${action.term} term with a ray`).not.toBeNull();
            }
            checked++;
          }
          expect(store.dispatch(action)).toBeUndefined();
        }
      }
      expect(checked).toBeGreaterThan(0);
    });
  }
});
