import { issueLine } from '../../src/util/issue.ts';
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import type { LabAction } from '../../src/lab-state/lab-action.ts';
import type { LabPanel } from '../../src/quest/lab-controls.ts';
import { loadLevels } from '../../src/quest/level-index.ts';
import { controlIdOf, isControlName } from '../../src/ui/lab/panels/control-ids.ts';

/**
 * The hint ring points at what the task's solution uses (issue 9): a task's `guide` is the
 * control that makes one of its solution's actions — "object.shininess" for a
 * `material.changed {shininess}`, "screen.pixel:3,2" for picking that pixel. The browser
 * test (e2e/guide-targets) checks that the ring's target is on screen and under the
 * pointer; this one checks, for every level, that it is the right target at all.
 */

const levelsFolder = new URL('../../levels/', import.meta.url);
const catalog = loadLevels(readFileSync(new URL('index.json', levelsFolder), 'utf8'), (name) => readFileSync(new URL(name, levelsFolder), 'utf8'));

/** Fields that are not the name of the control that edits them (control-ids.ts), or that several controls edit. */
const CONTROL_OF_FIELD: Partial<Record<LabAction['type'], Record<string, string[]>>> = {
  'object.changed': { position: ['gizmo.translate'], rotation: ['gizmo.rotate'], scale: ['gizmo.scale'] },
  'light.changed': { position: ['gizmo.translate'], rotation: ['gizmo.rotate'] },
  'camera.changed': { focusDistance: ['tracer.focus-distance', 'tracer.focus-on-selected'], pixels: ['tracer.pixels'] },
  'settings.changed': { lightTypes: ['tracer.light-types'] },
  'rays.changed': { showSamplePoints: ['tracer.show-sample-points'] },
  'bvh.changed': { showBounds: ['bvh.bounds'] },
};

/** The panel whose controls make an action's `changes`, field by field. */
const PANEL_OF_CHANGES: Partial<Record<LabAction['type'], LabPanel>> = {
  'object.changed': 'object',
  'material.changed': 'object',
  'light.changed': 'light',
  'camera.changed': 'tracer',
  'settings.changed': 'tracer',
  'rays.changed': 'rays',
  'bvh.changed': 'bvh',
};

/** The guide targets a learner could use to make `action`, or a reason why the test knows none. */
function targetsOf(action: LabAction): string[] {
  switch (action.type) {
    case 'selection.changed': {
      if (!action.selection) return ['view.canvas'];
      const id = action.selection.kind === 'camera' ? 'camera' : action.selection.id;
      return [`view.item:${id}`, `scene-list.item:${id}`];
    }
    case 'pixel.selected':
      return [`screen.pixel:${action.pixel.join(',')}`, 'screen.grid', 'screen-preview.grid'];
    case 'pixel.deselected':
      return ['screen.grid', 'screen-preview.grid'];
    case 'view.orbited':
      return ['view.orbit-buttons'];
    case 'view.panned':
      return ['view.pan-buttons'];
    case 'view.zoomed':
      return ['view.zoom-buttons'];
    case 'view.flew-to-camera':
      return ['view.fly-to-camera'];
    case 'gizmo.changed':
      return action.changes.mode ? [`gizmo.${action.changes.mode}`] : [];
    case 'panel.opened':
      return [`${action.panel}.open`];
    case 'render.started':
      return ['render.start'];
    case 'render.saved':
      return ['render.save'];
    case 'object.added':
      return ['add-remove.add-object'];
    case 'light.added':
      return ['add-remove.add-light'];
    case 'object.deleted':
    case 'light.deleted':
      return ['add-remove.delete'];
    case 'debugger.stepped':
      return ['debugger.step'];
    case 'debugger.term-clicked':
      return ['debugger.equation'];
    default:
      return 'changes' in action ? targetsOfChanges(action.type, action.changes as object) : [];
  }
}

/** A `changes` action's fields, each by its control (a material also changes by its presets). */
function targetsOfChanges(type: LabAction['type'], changes: object): string[] {
  const panel = PANEL_OF_CHANGES[type];
  if (!panel) return [];
  const targets = Object.keys(changes).flatMap((field) => {
    const named = CONTROL_OF_FIELD[type]?.[field];
    if (named) return named;
    const id = isControlName(panel, field) ? controlIdOf(panel, field) : undefined;
    if (!id) throw new Error(`no ${panel} control is known to change "${field}" (${type}): add it to CONTROL_OF_FIELD`);
    return [`${panel}.${id}`];
  });
  return type === 'material.changed' ? [...targets, 'object.presets'] : targets;
}

describe('every task guides to a control its solution uses', () => {
  it('finds the levels', () => {
    expect(catalog.errors).toEqual([]);
    expect(catalog.chapters.flatMap((chapter) => chapter.entries).length).toBeGreaterThanOrEqual(20);
  });

  for (const entry of catalog.chapters.flatMap((chapter) => chapter.entries)) {
    it(`${entry.id}`, () => {
      if (!entry.ok) throw new Error(`levels/${entry.id}.level.json is broken:\n${entry.errors.map(issueLine).join('\n')}`);
      const guided = entry.level.tasks.filter((task) => task.guide && task.solution);
      expect(guided.length, `${entry.id} has guided tasks`).toBeGreaterThan(0);
      for (const task of guided) {
        const targets = task.solution!.flatMap((action) => targetsOf(action as LabAction));
        expect(targets, `${entry.id}/${task.id}: the guide "${task.guide}" is a control its solution uses`).toContain(task.guide);
      }
    });
  }

  it('tells a guide that names another control apart', () => {
    const supersampling = targetsOf({ type: 'settings.changed', changes: { supersampling: 3 } });
    expect(supersampling).toEqual(['tracer.supersampling']);
    expect(supersampling).not.toContain('tracer.shadows');
    expect(targetsOf({ type: 'material.changed', id: 'ball', changes: { shininess: 200 } })).toEqual(['object.shininess', 'object.presets']);
    expect(targetsOf({ type: 'pixel.selected', pixel: [3, 2] })).toContain('screen.pixel:3,2');
    expect(targetsOf({ type: 'pixel.selected', pixel: [3, 2] })).not.toContain('screen.pixel:2,3');
    expect(() => targetsOf({ type: 'settings.changed', changes: { nonsense: 1 } as never })).toThrow(/no tracer control/);
  });
});
