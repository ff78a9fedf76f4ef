import { describe, expect, it } from 'vitest';
import { hasStrayMark, markedNames, markupParts, plainLevelText, plainText } from '../../src/quest/text-markup.ts';

describe('the on-screen names a level text marks with **', () => {
  const sentence = 'Set **Time samples (k)** under **Lens and shutter** to 4.';

  it('cut the text into plain and marked pieces, in order', () => {
    expect(markupParts(sentence)).toEqual([
      { text: 'Set ', marked: false },
      { text: 'Time samples (k)', marked: true },
      { text: ' under ', marked: false },
      { text: 'Lens and shutter', marked: true },
      { text: ' to 4.', marked: false },
    ]);
    expect(markupParts('**Render**')).toEqual([{ text: 'Render', marked: true }]);
    expect(markupParts('No names here.')).toEqual([{ text: 'No names here.', marked: false }]);
  });

  it('are listed, and taken out for plain text', () => {
    expect(markedNames(sentence)).toEqual(['Time samples (k)', 'Lens and shutter']);
    expect(plainText(sentence)).toBe('Set Time samples (k) under Lens and shutter to 4.');
    expect(plainLevelText({ en: 'Press **Render**.', nl: 'Druk op **Renderen**.' }, 'nl')).toBe('Druk op Renderen.');
  });

  it('end at the line: a mark without its partner stays as written, and is found', () => {
    const slip = 'Press **Render and\nthen **Save**.';
    expect(markedNames(slip)).toEqual(['Save']);
    expect(plainText(slip)).toBe('Press **Render and\nthen Save.');
    expect(hasStrayMark(slip)).toBe(true);
    expect(hasStrayMark(sentence)).toBe(false);
    expect(hasStrayMark('2 * 3 = 6, a * b')).toBe(false);
    expect(hasStrayMark('Press ****.')).toBe(true);
  });
});
