import { readdirSync, readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { phrasePattern, readDutchCatalogue } from '../support/dutch-catalogue.ts';

/**
 * A Dutch level text names each control as the Dutch UI labels it: "Druk op Beeld renderen",
 * not "Druk op Render image" beside a button that reads "Beeld renderen". The pairs come from
 * the catalogue (xliff/nl.xlf): every short message whose Dutch differs from its English. An
 * English label that Dutch writes too ("Render" in "Render de veranderde scène", "Delete" the
 * key) cannot be told from Dutch and is left out, as is any message with a placeholder.
 */

const catalogue = readDutchCatalogue();
const dutchMessages = catalogue.flatMap((message) => message.nl);

/** The labels to look for: short whole messages with letters, whose Dutch is not the English. */
const labels = catalogue
  .filter((message) => message.whole && message.en[0] !== message.nl[0] && /\p{L}/u.test(message.en[0]) && message.en[0].split(/\s+/).length <= 6)
  .map((message) => ({ en: message.en[0], nl: message.nl[0], pattern: phrasePattern(message.en[0]) }))
  .filter((label) => !dutchMessages.some((dutch) => label.pattern.test(dutch)));

/** Each English label `dutch` quotes, with the Dutch the UI shows for it. */
function englishLabelsIn(dutch: string): string[] {
  return labels.filter((label) => label.pattern.test(dutch)).map((label) => `"${label.en}" (the Dutch UI says "${label.nl}")`);
}

/** Every Dutch string of a level file, with where it is: texts, hints, quizzes, names. */
function dutchTexts(value: unknown, path: string): { path: string; text: string }[] {
  if (Array.isArray(value)) return value.flatMap((item, index) => dutchTexts(item, `${path}[${index}]`));
  if (typeof value !== 'object' || value === null) return [];
  return Object.entries(value).flatMap(([key, item]) =>
    key === 'nl' && typeof item === 'string' ? [{ path, text: item }] : dutchTexts(item, `${path}.${key}`),
  );
}

const levelsFolder = new URL('../../levels/', import.meta.url);
const levelFiles = readdirSync(levelsFolder).filter((name) => name.endsWith('.level.json'));

describe('the labels taken from the catalogue', () => {
  it('include the lab’s controls, and not the words Dutch shares with English', () => {
    const english = labels.map((label) => label.en);
    expect(english).toEqual(expect.arrayContaining(['Render image', 'Samples per side (n)', 'Recursion depth', 'Show rays']));
    expect(english).not.toContain('Render');
  });

  it('find an English label in a Dutch sentence, and the Dutch label is not one', () => {
    expect(englishLabelsIn('Druk op Render image bovenaan.')).toEqual(['"Render image" (the Dutch UI says "Beeld renderen")']);
    expect(englishLabelsIn('Druk op Beeld renderen bovenaan.')).toEqual([]);
    // A word that merely starts like a label is not the label.
    expect(englishLabelsIn('Zet Recursion depthfactor hoger.')).toEqual([]);
  });
});

describe('Dutch level texts', () => {
  it.each(levelFiles)('%s names the controls as the Dutch UI does', (file) => {
    const level: unknown = JSON.parse(readFileSync(new URL(file, levelsFolder), 'utf8'));
    const found = dutchTexts(level, '').flatMap(({ path, text }) => englishLabelsIn(text).map((label) => `${path}: ${label}`));
    expect(found).toEqual([]);
  });
});
