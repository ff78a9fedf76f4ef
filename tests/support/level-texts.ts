import type { LocalizedText } from '../../src/quest/localized-text.ts';

/**
 * Every text a learner reads in a level file, with where it is: titles, the intro, task
 * texts, "Explain more", hints, quiz questions, choices and explanations, figures' alt texts,
 * badges. A text is `{ "en": …, "nl": … }` wherever it is, or a plain (English) string under
 * one of the text fields. The scene, solutions, views, the ui and goals' values are data, not
 * texts, and are left out (the scene's names are on screen as names, not as sentences).
 */

export interface LevelText {
  path: string;
  text: LocalizedText;
}

/** The fields whose plain strings are texts (and, for lists, whose items are). */
const TEXT_FIELDS = new Set(['title', 'text', 'more', 'hints', 'question', 'choices', 'explanation', 'alt']);

/** Fields that hold data, not texts, even where a value in them looks like one (a scene's names, a goal's value). */
const DATA_FIELDS = new Set(['scene', 'solution', 'view', 'ui', 'with', 'where', 'value']);

export function levelTexts(value: unknown, path = '', field = ''): LevelText[] {
  if (typeof value === 'string') return TEXT_FIELDS.has(field) ? [{ path, text: value }] : [];
  if (Array.isArray(value)) return value.flatMap((item, index) => levelTexts(item, `${path}[${index}]`, field));
  if (typeof value !== 'object' || value === null) return [];
  const record = value as Record<string, unknown>;
  if (typeof record.en === 'string') return [{ path, text: record as { en: string; nl?: string } }];
  return Object.entries(record).flatMap(([key, item]) => (DATA_FIELDS.has(key) ? [] : levelTexts(item, path === '' ? key : `${path}.${key}`, key)));
}

/** The names the level's scene gives its objects and lights (and itself), in `language`: on screen in the scene list and the panels. */
export function sceneNames(level: unknown, language: 'en' | 'nl'): string[] {
  const scene = (level as { scene?: { name?: unknown; objects?: { name?: unknown }[]; lights?: { name?: unknown }[] } }).scene;
  const named = [scene?.name, ...(scene?.objects ?? []).map((item) => item.name), ...(scene?.lights ?? []).map((item) => item.name)];
  return named.flatMap((name) => {
    if (typeof name === 'string') return [name];
    if (typeof name === 'object' && name !== null && typeof (name as { en?: unknown }).en === 'string') {
      const text = name as { en: string; nl?: string };
      return [language === 'nl' ? (text.nl ?? text.en) : text.en];
    }
    return [];
  });
}
