import { describe, expect, it } from 'vitest';
import { inLanguage, levelTextIn } from '../../scripts/level-texts-plugin.ts';

/** The level files in one language: what a learner's browser loads (scripts/level-texts-plugin.ts). */
describe('a level file in one language', () => {
  const level = {
    title: { en: 'Shadows', nl: 'Schaduwen' },
    intro: { text: 'Only English' },
    tasks: [{ id: 'a', hints: [{ en: 'Look', nl: 'Kijk' }, { en: 'No Dutch yet' }], goal: { state: 'scene.settings.shadows', op: '==', value: false } }],
    scene: { objects: [{ id: 'ball', position: [0, 1, 0], name: { en: 'Ball', nl: 'Bal' } }] },
  };

  it('has each text in that language, English where it has none, and everything else unchanged', () => {
    expect(inLanguage(level, 'nl')).toEqual({
      title: 'Schaduwen',
      intro: { text: 'Only English' },
      tasks: [{ id: 'a', hints: ['Kijk', 'No Dutch yet'], goal: { state: 'scene.settings.shadows', op: '==', value: false } }],
      scene: { objects: [{ id: 'ball', position: [0, 1, 0], name: 'Bal' }] },
    });
    expect(inLanguage(level, 'en')).toMatchObject({ title: 'Shadows', tasks: [{ hints: ['Look', 'No Dutch yet'] }] });
  });

  it('keeps a file that is not JSON as written, so the game can say why it is broken', () => {
    expect(levelTextIn('{ "version": 1, broken', 'nl')).toBe('{ "version": 1, broken');
    expect(JSON.parse(levelTextIn(JSON.stringify(level), 'nl')).title).toBe('Schaduwen');
  });
});
