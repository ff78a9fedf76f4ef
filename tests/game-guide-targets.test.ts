import { describe, expect, it } from 'vitest';
import { CONTROL_TARGETS } from '../src/quest/lab-controls.ts';
import { CONTROL_PATHS, hiddenControlsCss, hiddenToolbarCss, itemPosition, locateGuideTarget } from '../src/ui/guide-targets.ts';

describe('guide target names → places on the page', () => {
  it('finds a panel control by its name attribute inside the panel', () => {
    expect(locateGuideTarget('tracer.supersampling')).toEqual({ kind: 'element', path: ['rt-tracer-panel', '[name="supersampling"]'] });
    expect(locateGuideTarget('object.refractive-index')).toEqual({ kind: 'element', path: ['rt-object-panel', '[name="refractiveIndex"]'] });
  });

  it('finds view buttons by their data-command inside the toolbar', () => {
    expect(locateGuideTarget('view.fly-to-camera')).toEqual({ kind: 'element', path: ['rt-scene-view', 'rt-view-toolbar', '[data-command="fly"]'] });
    expect(locateGuideTarget('render.open')).toEqual({ kind: 'element', path: ['[data-command="render-open"]'] });
    // Not by its aria-label, which is in the learner's language.
    expect(locateGuideTarget('render.close')).toEqual({ kind: 'element', path: ['rt-render-window', '[data-command="render-close"]'] });
  });

  it('reads items and pixels', () => {
    expect(locateGuideTarget('view.item:ball')).toEqual({ kind: 'view-item', id: 'ball' });
    expect(locateGuideTarget('screen.pixel:3,2')).toEqual({ kind: 'pixel', column: 3, row: 2 });
    expect(locateGuideTarget('screen.grid')).toEqual({ kind: 'camera-screen' });
    const row = locateGuideTarget('scene-list.item:lamp');
    expect(row?.kind === 'element' && row.path.at(-1)).toContain('[data-key="light:lamp"]');
  });

  it('refuses what is not a target', () => {
    expect(locateGuideTarget('tracer.nonsense')).toBeUndefined();
    expect(locateGuideTarget('screen.pixel:a,b')).toBeUndefined();
    expect(locateGuideTarget('view.item:')).toBeUndefined();
  });

  it('finds the file and BVH panels\' controls by their names', () => {
    expect(locateGuideTarget('file.save')).toEqual({ kind: 'element', path: ['rt-file-panel', '[name="save"]'] });
    expect(locateGuideTarget('bvh.depth')).toEqual({ kind: 'element', path: ['rt-bvh-panel', '[name="depth"]'] });
  });

  it('has a place (or an explicit none) for every control name levels may use', () => {
    expect(Object.keys(CONTROL_PATHS).sort()).toEqual([...CONTROL_TARGETS].sort());
  });

  it('finds the position of an object or a light', () => {
    const scene = { objects: [{ id: 'ball', position: [1, 2, 3] as [number, number, number] }], lights: [{ id: 'lamp', position: [4, 5, 6] as [number, number, number] }] };
    expect(itemPosition(scene, 'ball')).toEqual([1, 2, 3]);
    expect(itemPosition(scene, 'lamp')).toEqual([4, 5, 6]);
    expect(itemPosition(scene, 'nothing')).toBeUndefined();
  });
});

describe('a level narrows the panels', () => {
  it('hides the controls it leaves out, and keeps the ones it lists', () => {
    const css = hiddenControlsCss('tracer', ['pixels']);
    expect(css).toContain(':not([name^="pixels."])');
    expect(hiddenControlsCss('tracer', undefined)).toBe('');
    expect(hiddenControlsCss('view', ['canvas'])).toBe('');
  });

  it('hides the gizmo buttons a level does not show', () => {
    expect(hiddenToolbarCss(true, undefined)).toBe('');
    const some = hiddenToolbarCss(true, ['translate', 'rotate', 'scale']);
    expect(some).toContain('[data-command="toggle-space"]');
    expect(some).not.toMatch(/\[data-command="translate"\][^]*\{/);
    expect(hiddenToolbarCss(false, undefined)).toContain('[data-command="translate"]');
  });
});
