import { describe, expect, it } from 'vitest';
import bankFile from '../../src/classroom/concept-test/concept-bank.json';
import { parseConceptBank, type ConceptBank, type ConceptItem } from '../../src/classroom/concept-test/concept-bank-schema.ts';
import { LOCALES, type LocalizedText } from '../../src/quest/localized-text.ts';
import { keyIsLongest, keyStandsOut } from '../support/key-stands-out.ts';

/**
 * The concept test's item bank (issue 40): parallel forms A and B that measure the same
 * concepts, every wrong choice a named misconception, and keys a pupil cannot pick by their
 * form. The gain per concept (Hake 1998) is only fair when both forms ask as much of each.
 */

const parsed = parseConceptBank(bankFile);
if (!parsed.ok) throw new Error(`concept-bank.json does not parse:\n${parsed.errors.join('\n')}`);
const bank: ConceptBank = parsed.bank;

/** A text in one language, with no fallback to English: a missing translation is an error here. */
function inLocale(text: LocalizedText, locale: (typeof LOCALES)[number]): string {
  return typeof text === 'string' ? (locale === 'en' ? text : '') : (text[locale] ?? '');
}

/** Concept id → how many items of the form ask about it. */
function conceptCounts(form: 'A' | 'B'): Map<string, number> {
  const counts = new Map<string, number>();
  for (const item of bank.items.filter((each) => each.form === form)) counts.set(item.concept, (counts.get(item.concept) ?? 0) + 1);
  return counts;
}

const named = (item: ConceptItem) => ({ name: item.id, item });

describe('the length rules', () => {
  it('flag a key that is the longest or stands out, and pass a balanced set', () => {
    expect(keyIsLongest(['short', 'longer one', 'the longest of all'], 2)).toBe(true);
    expect(keyIsLongest(['same size', 'same size', 'tiny'], 0)).toBe(false);
    expect(keyStandsOut(['a much longer and careful answer', 'red', 'blue'], 0)).toBe(true);
    expect(keyStandsOut(['x', 'a long careful answer here', 'another long careful one'], 0)).toBe(true);
    expect(keyStandsOut(['smaller and sharper', 'bigger and softer', 'red like the ball'], 0)).toBe(false);
  });
});

describe('the concept bank', () => {
  it('parses, with at least 12 pairs of an item of form A and one of form B', () => {
    expect(parseConceptBank(bankFile)).toMatchObject({ ok: true });
    expect(bank.items.length).toBeGreaterThanOrEqual(24);
    expect(new Set(bank.items.map((item) => item.pair)).size * 2).toBe(bank.items.length);
  });

  it("covers the issue's core ideas, each concept with at least one pair", () => {
    const core = ['backward-tracing', 'shading', 'shadows', 'reflection', 'refraction', 'attenuation', 'soft-shadows', 'aliasing'];
    const later = ['depth-of-field', 'glossy-reflection', 'motion-blur'];
    expect(bank.concepts.map((concept) => concept.id)).toEqual(expect.arrayContaining([...core, ...later]));
    for (const concept of bank.concepts) {
      const pairs = new Set(bank.items.filter((item) => item.concept === concept.id).map((item) => item.pair));
      expect(pairs.size, concept.id).toBeGreaterThanOrEqual(1);
    }
  });

  it('has forms A and B of the same size, asking about the same concepts as often', () => {
    const a = conceptCounts('A');
    const b = conceptCounts('B');
    expect(bank.items.filter((item) => item.form === 'A')).toHaveLength(bank.items.length / 2);
    expect([...a].sort()).toEqual([...b].sort());
  });

  it('names its concepts in every language', () => {
    for (const concept of bank.concepts) for (const locale of LOCALES) expect(inLocale(concept.name, locale).trim(), `${concept.id} ${locale}`).not.toBe('');
  });
});

describe.each(LOCALES)('every item, in %s', (locale) => {
  it.each(bank.items.map(named))('$name: its texts are there, and its key is not given away by its form', ({ item }) => {
    const question = inLocale(item.question, locale);
    const choices = item.choices.map((choice) => inLocale(choice.text, locale));
    expect(question.trim()).not.toBe('');
    for (const choice of choices) expect(choice.trim()).not.toBe('');
    const key = item.choices.findIndex((choice) => choice.id === item.answer);
    expect(keyIsLongest(choices, key), `the key is the longest choice: ${choices.join(' | ')}`).toBe(false);
    expect(keyStandsOut(choices, key), `the key stands out by its length: ${choices.join(' | ')}`).toBe(false);
    // "All of the above" is right or wrong by the other choices, not by the idea asked.
    for (const choice of choices)
      expect(choice.toLowerCase()).not.toMatch(/all of the above|none of the above|alle bovenstaande|geen van (de|alle) bovenstaande/);
    // Numbers the way each language writes them (docs/i18n.md): 1.33 in English, 1,33 in Dutch.
    const wrongDecimal = locale === 'nl' ? /\d\.\d/ : /\d,\d/;
    for (const text of [question, ...choices]) expect(text, 'a decimal separator of the other language').not.toMatch(wrongDecimal);
    // The question does not hold the key's phrase (a short key, "half", may be there for other reasons).
    if (choices[key].length >= 16) expect(question.toLowerCase()).not.toContain(choices[key].toLowerCase());
  });

  it.each(bank.items.map(named))('$name: every wrong choice names its misconception, the key none', ({ item }) => {
    for (const choice of item.choices) {
      if (choice.id === item.answer) expect(choice.misconception, choice.id).toBeUndefined();
      else expect(inLocale(choice.misconception ?? '', locale).trim(), choice.id).not.toBe('');
    }
  });
});
