// The names of a level's objects and lights as the panels, the scene list and the ray tooltip
// show them: in the app's language when the scene gives one per language, as written when it
// gives a plain name (older scene files), and the id when there is none. The language is
// switched for real, on a stand-in page (these tests run without a browser).
import { afterAll, beforeAll, describe, expect, it, vi } from 'vitest';
import { defaultScene } from '../../../src/scene/scene-defaults.ts';
import type { Scene } from '../../../src/scene/scene.ts';
import { standInPage } from '../../support/page-locale.ts';

describe('names of what is in the scene', () => {
  let names: typeof import('../../../src/ui/lab/scene-names.ts');
  let speak: (locale: 'en' | 'nl') => Promise<void>;
  const base = defaultScene();
  const scene: Scene = {
    ...base,
    objects: [
      { ...base.objects[0], id: 'ball', name: { en: 'Red ball', nl: 'Rode bal' } },
      { ...base.objects[1], id: 'box', name: 'Old box' },
      { ...base.objects[2], id: 'cube-1', name: undefined },
    ],
    lights: [{ ...base.lights[0], id: 'key', name: { en: 'Key light' } }],
  };

  beforeAll(async () => {
    speak = await standInPage();
    names = await import('../../../src/ui/lab/scene-names.ts');
  });

  afterAll(() => {
    vi.unstubAllGlobals();
  });

  it('are Dutch in Dutch, English in English, and fall back to English, the plain name or the id', async () => {
    const shown = () => ['ball', 'box', 'cube-1', 'key', 'gone'].map((id) => names.itemName(scene, id));
    await speak('nl');
    expect(shown()).toEqual(['Rode bal', 'Old box', 'cube-1', 'Key light', 'gone']);
    await speak('en');
    expect(shown()).toEqual(['Red ball', 'Old box', 'cube-1', 'Key light', 'gone']);
  });

  it('give the scene its name, or what the caller has for a scene without one', async () => {
    await speak('nl');
    expect(names.shownName({ en: 'A ball and a box', nl: 'Een bal en een doos' }, 'Naamloos')).toBe('Een bal en een doos');
    expect(names.shownName(undefined, 'Naamloos')).toBe('Naamloos');
    await speak('en');
  });
});
