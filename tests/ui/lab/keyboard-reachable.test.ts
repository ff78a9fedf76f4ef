import { existsSync, readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { loadLevels } from '../../../src/quest/level-index.ts';
import type { Level } from '../../../src/quest/level-schema.ts';
import type { LabAction } from '../../../src/lab-state/lab-action.ts';
import { levelPanels } from '../../../src/ui/lab/level-panels.ts';
import { type GizmoMode, gizmoModesFor } from '../../../src/view/gizmo-modes.ts';

/**
 * Every mandatory task can be earned by keyboard. Panel controls are native inputs and the
 * view's commands all have keys (tests/view/view-commands.test.ts); selecting is N, a pixel
 * is P and the arrows. What needed a mouse is a drag: a move, turn or scale of an object, a
 * light or the camera. The keys do those in the gizmo's mode while its handles are shown,
 * so each transform a mandatory task's solution makes must be in a gizmo mode that the level
 * offers and the item allows (an area light's size also has its own field in the light panel).
 */

const levelsFolder = new URL('../../../levels/', import.meta.url);
const readLevelFile = (name: string) => (existsSync(new URL(name, levelsFolder)) ? readFileSync(new URL(name, levelsFolder), 'utf8') : undefined);
const catalog = loadLevels(readFileSync(new URL('index.json', levelsFolder), 'utf8'), readLevelFile);
const levels = catalog.chapters.flatMap((chapter) => chapter.entries.flatMap((entry) => (entry.ok ? [entry.level] : [])));

const MODE_OF_FIELD: Readonly<Record<string, GizmoMode>> = { position: 'translate', target: 'rotate', rotation: 'rotate', scale: 'scale', size: 'scale' };

/** The transforms an action makes that only a drag or the keys can make, as "what: mode" for the ones the keys cannot reach in `level`. */
function unreachable(level: Level, action: LabAction): string[] {
  if (action.type !== 'object.changed' && action.type !== 'light.changed' && action.type !== 'camera.changed') return [];
  const selection =
    action.type === 'object.changed'
      ? { kind: 'object' as const, id: action.id }
      : action.type === 'light.changed'
        ? { kind: 'light' as const, id: action.id }
        : { kind: 'camera' as const };
  const allowed = gizmoModesFor(selection, level.scene);
  const offered = levelPanels(level).gizmo;
  const { panels, controls } = levelPanels(level);
  const sizeField = panels.has('light') && (controls('light')?.includes('size') ?? true);
  return Object.keys(action.changes).flatMap((field) => {
    const mode = MODE_OF_FIELD[field];
    if (!mode) return [];
    if (field === 'size' && sizeField) return [];
    const byKeys = allowed.includes(mode) && (offered === undefined || offered.includes(mode));
    return byKeys ? [] : [`${action.type} ${field}: needs the ${mode} gizmo`];
  });
}

describe('every mandatory task by keyboard', () => {
  it('finds the levels and their mandatory moves (the ball, the lamp, the spot)', () => {
    expect(levels.length).toBeGreaterThanOrEqual(20);
    const moves = levels.flatMap((level) =>
      level.tasks
        .filter(
          (task) =>
            task.mandatory !== false &&
            (task.solution ?? []).some(
              (action) =>
                ['object.changed', 'light.changed', 'camera.changed'].includes(action.type) &&
                'changes' in action &&
                Object.keys(action.changes as object).some((field) => field in MODE_OF_FIELD),
            ),
        )
        .map((task) => `${level.id}/${task.id}`),
    );
    expect(moves).toEqual(expect.arrayContaining(['01-introduction/move-ball', '04-shadows/move-lamp', '14-finding-your-way/fix-spot']));
  });

  for (const level of levels) {
    it(`${level.id}: each transform of a mandatory task is in a gizmo mode the level offers`, () => {
      const problems = level.tasks
        .filter((task) => task.mandatory !== false)
        .flatMap((task) => (task.solution ?? []).flatMap((action) => unreachable(level, action as LabAction).map((problem) => `${task.id}: ${problem}`)));
      expect(problems).toEqual([]);
    });
  }

  it('would catch a move in a level without move tools', () => {
    const level = levels.find((l) => l.id === '08-spot-lights')!;
    expect(unreachable(level, { type: 'light.changed', id: 'lamp', changes: { position: [0, 2, 0] } })).toEqual([
      'light.changed position: needs the translate gizmo',
    ]);
  });
});
