import { readFileSync } from 'node:fs';
import { describe, expect, expectTypeOf, it } from 'vitest';
import { guideIds, ITEM_TARGETS, LAB_CONTROLS, type ControlOf, type LabPanel } from '../../../src/quest/lab-controls.ts';
import { CONTROL_NAMES, controlIdOf, isControlName, type ControlName, type UnreachedIds } from '../../../src/ui/lab/panels/control-ids.ts';

/**
 * A panel's controls are named from a declared list (control-ids.ts), not by a kebab-case
 * rule: issue 39 renamed `spotAngle` and level 8 lost its slider and its hint ring while tsc
 * and the unit tests passed. Renames now fail to compile (the @ts-expect-error lines below
 * are checked by `tsc --noEmit`), and every id a level file names must be one a control
 * answers to. tests/components/ checks that each panel draws them.
 */

const levelsFolder = new URL('../../../levels/', import.meta.url);

interface LevelFile {
  id: string;
  ui?: { panels?: string[]; controls?: Record<string, string[]> };
  tasks: { id: string; guide?: string }[];
}

const levelIds = (JSON.parse(readFileSync(new URL('index.json', levelsFolder), 'utf8')) as { chapters: { levels: string[] }[] }).chapters.flatMap(
  (chapter) => chapter.levels,
);
const levels = levelIds.map((id) => JSON.parse(readFileSync(new URL(`${id}.level.json`, levelsFolder), 'utf8')) as LevelFile);

const isPanel = (name: string): name is LabPanel => Object.hasOwn(LAB_CONTROLS, name);

/** Whether some control of `panel` answers to the level id `id`. */
function drawnId(panel: string, id: string): boolean {
  if (!isPanel(panel) || !(LAB_CONTROLS[panel] as readonly string[]).includes(id)) return false;
  const names: Readonly<Record<string, string | null>> | undefined = (CONTROL_NAMES as Partial<Record<LabPanel, Record<string, string | null>>>)[panel];
  return names === undefined || Object.values(names).includes(id);
}

describe("each panel declares its controls' names", () => {
  it('maps each name to the id levels use, grouped names to one id, and position fields to none', () => {
    expect(controlIdOf('object', 'refractiveIndex')).toBe('refractive-index');
    expect(controlIdOf('light', 'spotAngle')).toBe('spot-angle');
    expect(controlIdOf('tracer', 'pixels.columns')).toBe('pixels');
    expect(controlIdOf('tracer', 'lightTypes.area')).toBe('light-types');
    expect(controlIdOf('rays', 'showRays')).toBe('show');
    expect(controlIdOf('rays', 'colorBlindPalette')).toBe('color-blind');
    expect(controlIdOf('object', 'position')).toBeUndefined();
    expect(controlIdOf('tracer', 'imageSize')).toBeUndefined();
    expect(controlIdOf('debugger', 'why-dark')).toBe('why-dark');
  });

  it('refuses a renamed control at compile time', () => {
    // @ts-expect-error a renamed slider is not one of the light panel's names
    expect(controlIdOf('light', 'spotAngleDegrees')).toBeUndefined();
    // @ts-expect-error the level id is not the element's name: no kebab-case rule guesses it
    expect(controlIdOf('light', 'spot-angle')).toBeUndefined();
    // @ts-expect-error a control of another panel
    expect(controlIdOf('rays', 'supersampling')).toBeUndefined();
    expectTypeOf<'spotAngle'>().toExtend<ControlName<'light'>>();
    expectTypeOf<'spotAngleDegrees'>().not.toExtend<ControlName<'light'>>();
    // Panels whose elements use the level ids themselves accept exactly those.
    expectTypeOf<ControlName<'debugger'>>().toEqualTypeOf<ControlOf<'debugger'>>();
  });

  it('names, at compile time, a level id that lost its control', () => {
    type WithoutSpotAngle = Omit<typeof CONTROL_NAMES.light, 'spotAngle'>;
    expectTypeOf<UnreachedIds<'light', WithoutSpotAngle>>().toEqualTypeOf<'spot-angle'>();
    expectTypeOf<UnreachedIds<'light', typeof CONTROL_NAMES.light>>().toBeNever();
  });

  it('gives every id of a named panel a control, and only ids that exist', () => {
    for (const [panel, names] of Object.entries(CONTROL_NAMES) as [LabPanel, Record<string, string | null>][]) {
      const ids = Object.values(names).filter((id) => id !== null);
      expect(new Set(ids), panel).toEqual(new Set(LAB_CONTROLS[panel]));
    }
  });

  it('tells names read at run time apart', () => {
    expect(isControlName('light', 'spotAngle')).toBe(true);
    expect(isControlName('light', 'spot-angle')).toBe(false);
    expect(isControlName('debugger', 'why-dark')).toBe(true);
    expect(isControlName('debugger', 'whyDark')).toBe(false);
  });
});

describe("guide ids written by hand (the render window, the view's buttons)", () => {
  it('joins declared targets, and refuses one that is not declared at compile time', () => {
    expect(guideIds('render.zoom', 'render.compare')).toBe('render.zoom render.compare');
    // @ts-expect-error the render window has no "begin": its button is "render.start"
    expect(guideIds('render.begin')).toBe('render.begin');
  });
});

describe('every level names only controls that exist', () => {
  it('reads all the levels', () => {
    expect(levels.length).toBeGreaterThanOrEqual(20);
    expect(levels.find((level) => level.id === '08-spot-lights')?.ui?.controls?.light).toContain('spot-angle');
  });

  it('knows a missing control when it sees one', () => {
    expect(drawnId('light', 'spot-angle')).toBe(true);
    expect(drawnId('light', 'spot-angel')).toBe(false);
    expect(drawnId('lamp', 'spot-angle')).toBe(false);
  });

  for (const level of levels) {
    it(level.id, () => {
      for (const [panel, ids] of Object.entries(level.ui?.controls ?? {})) {
        for (const id of ids) expect(drawnId(panel, id), `${level.id}: ui.controls.${panel} names "${id}"`).toBe(true);
      }
      for (const task of level.tasks) {
        if (!task.guide) continue;
        const [name, item] = task.guide.split(/:(.*)/s, 2);
        if (item !== undefined) {
          expect(ITEM_TARGETS as readonly string[], `${level.id}/${task.id}: guide "${task.guide}"`).toContain(name);
          continue;
        }
        const dot = task.guide.indexOf('.');
        expect(drawnId(task.guide.slice(0, dot), task.guide.slice(dot + 1)), `${level.id}/${task.id}: guide "${task.guide}"`).toBe(true);
      }
    });
  }
});
