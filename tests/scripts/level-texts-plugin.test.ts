import { describe, expect, it } from 'vitest';
import { inLanguage, levelTextWithoutMore } from '../../scripts/level-texts-plugin.ts';
import { LATER_TEXT_KEY } from '../../src/quest/later-text-key.ts';

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
    const later: Record<string, string> = {};
    expect(levelTextWithoutMore('x.level.json', '{ "version": 1, broken', 'nl', later)).toBe('{ "version": 1, broken');
    expect(JSON.parse(levelTextWithoutMore('x.level.json', JSON.stringify(level), 'nl', later)).title).toBe('Schaduwen');
    expect(later).toEqual({});
  });

  it('takes the "Explain more" texts out to load later, each replaced by its key', () => {
    const withMore = {
      ...level,
      intro: { text: 'Hi', more: { en: 'Why', nl: 'Waarom' } },
      tasks: [{ ...level.tasks[0], more: { en: 'Deeper', nl: 'Dieper' } }, { id: 'b' }],
    };
    const later: Record<string, string> = {};
    const shown = JSON.parse(levelTextWithoutMore('04.level.json', JSON.stringify(withMore), 'nl', later));
    expect(shown.intro).toEqual({ text: 'Hi', more: `${LATER_TEXT_KEY}04.level.json#intro` });
    expect(shown.tasks[0].more).toBe(`${LATER_TEXT_KEY}04.level.json#task-0`);
    expect(shown.tasks[1]).toEqual({ id: 'b' });
    expect(later).toEqual({ '04.level.json#intro': 'Waarom', '04.level.json#task-0': 'Dieper' });
  });
});
