// The words for rays in the legend, the tooltip and the ray debugger: one meaning of "shadow
// ray" everywhere (a ray toward a light that tests what is in the way: it reaches the light or
// is blocked), the direction to a light with Shadows off named as not tested, and the normal.
// In English and in Dutch, switched for real on a stand-in page (no browser).
import { afterAll, beforeAll, describe, expect, it, vi } from 'vitest';
import { defaultScene } from '../../../src/scene/scene-defaults.ts';
import type { Scene } from '../../../src/scene/scene.ts';
import type { RayNode } from '../../../src/tracer/ray-tree.ts';
import type { DebugStep } from '../../../src/debugger/debug-steps.ts';
import { RAY_COLOR_KEYS } from '../../../src/view/ray-palette.ts';
import { standInPage } from '../../support/page-locale.ts';
import { areaRay, ray } from '../../support/ray-fixtures.ts';

describe('names of rays', () => {
  let names: typeof import('../../../src/ui/lab/ray-names.ts');
  let traced: typeof import('../../../src/ui/lab/traced-ray-text.ts');
  let debuggerText: typeof import('../../../src/ui/lab/debugger/debugger-text.ts');
  let speak: (locale: 'en' | 'nl') => Promise<void>;
  const base = defaultScene();
  const scene: Scene = {
    ...base,
    objects: [{ ...base.objects[0], id: 'ball', name: { en: 'Ball', nl: 'Bal' } }],
    lights: [{ ...base.lights[0], id: 'lamp', name: { en: 'Lamp', nl: 'Lamp' } }],
  };
  const itemName = (id: string | null) => (id === 'ball' ? 'Ball' : id === 'lamp' ? 'Lamp' : (id ?? ''));
  const reached = ray('light', { lightId: 'lamp' });
  const blocked = ray('shadow', { lightId: 'lamp', objectId: 'ball', color: [0, 0, 0] });
  const untested = ray('light', { lightId: 'lamp', untested: true });
  const lightStep = (node: RayNode): DebugStep => ({
    kind: 'light',
    line: 'lit',
    ray: node,
    hit: null,
    from: null,
    depth: 0,
    sample: 0,
    level: 1,
    place: null,
    share: 1,
    adds: node.color,
    sum: node.color,
  });

  beforeAll(async () => {
    speak = await standInPage();
    names = await import('../../../src/ui/lab/ray-names.ts');
    traced = await import('../../../src/ui/lab/traced-ray-text.ts');
    debuggerText = await import('../../../src/ui/lab/debugger/debugger-text.ts');
  });

  afterAll(() => {
    vi.unstubAllGlobals();
  });

  it('call both rays toward a light shadow rays, one reaching the light and one blocked, in both languages', async () => {
    expect(names.rayColorKeyName('light')).toBe('Shadow ray — reaches the light');
    expect(names.rayColorKeyName('shadow')).toBe('Shadow ray — blocked');
    expect(traced.rayName(reached)).toBe('Shadow ray — reaches the light');
    expect(traced.rayName(areaRay('area-shadow'))).toBe('Shadow rays to an area light — all blocked (cone)');
    for (const key of ['light', 'shadow'] as const)
      expect(names.rayColorKeyHint(key)).toMatch(/^A shadow ray tests whether anything is between the point and a light\./);
    await speak('nl');
    expect(names.rayColorKeyName('light')).toBe('Schaduwstraal — bereikt de lamp');
    expect(names.rayColorKeyName('shadow')).toBe('Schaduwstraal — geblokkeerd');
    expect(traced.rayName(areaRay('area-light'))).toBe('Schaduwstralen naar een vlaklamp — bereiken hem allemaal (kegel)');
    // No "light ray" (lichtstraal) left for a ray toward a light, and one Dutch word for blocked.
    const dutch = RAY_COLOR_KEYS.flatMap((key) => [names.rayColorKeyName(key), names.rayColorKeyHint(key)]).join(' ');
    expect(dutch).not.toMatch(/lichtstra|tegengehouden/i);
    await speak('en');
    const english = RAY_COLOR_KEYS.flatMap((key) => [names.rayColorKeyName(key), names.rayColorKeyHint(key)]).join(' ');
    expect(english).not.toMatch(/light ray/i);
  });

  it('name the direction to a light with Shadows off as not tested, never as a ray that reached it', async () => {
    expect(traced.rayName(untested)).toBe('Direction to the light — not tested, Shadows is off');
    expect(traced.rayName(areaRay('area-light', { untested: true }))).toBe('Directions to an area light — not tested, Shadows is off (cone)');
    expect(traced.rayTargetText(untested, 'untested', itemName)).toBe(
      'Not tested: Shadows is off, so no shadow ray was cast and Lamp counts as reaching this point, even through an object.',
    );
    expect(traced.rayTargetText(reached, 'light', itemName)).toBe('Reaches Lamp: nothing is in the way');
    expect(traced.rayTargetText(blocked, 'shadow', itemName)).toBe('Blocked by Ball on its way to Lamp');
    await speak('nl');
    expect(traced.rayName(untested)).toBe('Richting naar de lamp — niet getest, Schaduwen staat uit');
    expect(traced.rayTargetText(blocked, 'shadow', itemName)).toBe('Op weg naar Lamp geblokkeerd door Ball');
    await speak('en');
  });

  it('name the normal drawn at a hit, and what it stands for', async () => {
    const primary = ray('primary', { objectId: 'ball', normal: [0, 1, 0] });
    expect(names.rayColorKeyName('normal')).toBe('Normal');
    expect(traced.rayTargetText(primary, 'normal', itemName)).toBe(
      'The normal at the hit on Ball: straight out of the surface, on the side the ray came from.',
    );
    expect(traced.rayTargetText(primary, 'primary', itemName)).toBe('Hits Ball');
    await speak('nl');
    expect(names.rayColorKeyName('normal')).toBe('Normaal');
    await speak('en');
  });

  it('the debugger says the same: a shadow ray reaches the light or is blocked; with Shadows off none is cast', async () => {
    expect(debuggerText.stepText(lightStep(reached), scene)).toBe('The shadow ray to Lamp reaches it: its diffuse and highlight are added.');
    expect(debuggerText.stepText(lightStep(blocked), scene)).toBe('The shadow ray to Lamp is blocked by Ball: S = 0.');
    expect(debuggerText.stepText(lightStep(untested), scene)).toBe(
      'Shadows is off: no shadow ray is cast, so Lamp counts as reaching the point: its diffuse and highlight are added.',
    );
    expect(debuggerText.pseudocodeText('shadow-ray')).toBe('if N·L > 0, A > 0 and Shadows is on: cast a shadow ray toward the light');
    await speak('nl');
    expect(debuggerText.stepText(lightStep(reached), scene)).toBe(
      'De schaduwstraal naar Lamp bereikt die lamp: het diffuse licht en de glansvlek worden opgeteld.',
    );
    expect(debuggerText.pseudocodeText('shadow-ray')).toBe('als N·L en A groter dan 0 zijn en Schaduwen aan staat: stuur een schaduwstraal naar de lamp');
    await speak('en');
  });
});
