import { markedNames } from '../../src/quest/text-markup.ts';
import type { CatalogueMessage } from './dutch-catalogue.ts';

/**
 * The words the screen shows, per language, and two checks of a level text against them
 * (tests/i18n/level-text-names.test.ts): every name the text marks (`**Render image**`) is
 * one of them, and no phrase that names a panel or a control ("the Ray tracer panel",
 * "press Render", "onder Lens en sluiter") leaves its name unmarked.
 *
 * The words are the UI's messages (`msg()`), from the catalogue (xliff/nl.xlf): its sources
 * are the English screen, its targets the Dutch one (the source where a message has no
 * target yet: the Dutch screen then shows the English). A message with a placeholder, such as
 * "Focus on ${name}" or "${s} × ${s} = ${s * s} rays per pixel", is a pattern: any text in
 * the placeholder's place.
 */

export type Language = 'en' | 'nl';

export interface ScreenWords {
  language: Language;
  /** Messages without a placeholder, as written. */
  exact: ReadonlySet<string>;
  /** Messages with a placeholder, whole: "Focus on ${name}" as /^Focus on .+$/. */
  patterns: readonly RegExp[];
  /** The names of the level's own objects and lights ("Lamp", "Red ball"): on screen, but names of things rather than of controls. */
  items: readonly string[];
  /** Every word of the short labels, in lower case ("tracer" of "Ray tracer"): a word the screen uses for a control. */
  labelWords: ReadonlySet<string>;
  /** The first word of every label and item ("Lens" of "Lens and shutter"), as written. */
  firstWords: ReadonlySet<string>;
  /** The short labels of two words or more that begin with a capital ("Debug a pixel"), as one pattern for any of them, whole. */
  phrases: RegExp;
}

/** A trailing ':' or '…' belongs to the sentence a label sits in on screen ("Badges earned:"), not to its name. */
const TRAILING = /\s*(?::|…|\.\.\.)$/;

function escape(text: string): string {
  return text.replace(/[.*+?^${}()|[\]\\]/g, '\\$&');
}

/**
 * Words that stand before "panel", "button"… without naming it, though a label has them:
 * "the first slider", "the next button", "the mouse button" (the one on the mouse).
 */
const NOT_NAMES = new Set([
  'the',
  'this',
  'that',
  'same',
  'other',
  'first',
  'second',
  'last',
  'next',
  'new',
  'top',
  'left',
  'right',
  'mouse',
  'all',
  'one',
  'each',
  'every',
  'and',
  'then',
]);

/** Words of labels that are not a control's name on their own ("Show its rays", "Your own scene"). */
const SMALL_WORDS = new Set([
  'for',
  'from',
  'with',
  'into',
  'its',
  'you',
  'your',
  'also',
  'both',
  'more',
  'less',
  'not',
  'per',
  'off',
  'out',
  'own',
  'are',
  'was',
]);

/** Labels up to this many words are a control's name; longer messages are sentences, whose words say nothing. */
const LABEL_WORDS_MAX = 4;

/** The screen's words in `language`, with `items`, the names of the level's own objects and lights. */
export function screenWords(catalogue: readonly CatalogueMessage[], language: Language, items: readonly string[] = []): ScreenWords {
  const exact = new Set<string>();
  const patterns: RegExp[] = [];
  for (const message of catalogue) {
    const parts = language === 'nl' && message.nl.join('') !== '' ? message.nl : message.en;
    if (message.whole) {
      exact.add(parts[0]);
      exact.add(parts[0].replace(TRAILING, ''));
    } else if (/\p{L}/u.test(parts.join(''))) {
      // A placeholder alone ("${name}: ${value}") would match any name, so only patterns with words of their own count.
      patterns.push(new RegExp(`^${parts.map(escape).join('.+')}$`, 'u'));
    }
  }
  const labelWords = new Set(
    [...exact]
      .map((label) => label.split(/\s+/))
      .filter((words) => words.length <= LABEL_WORDS_MAX)
      .flat()
      .map((word) => word.toLowerCase().replace(/[^\p{L}\p{N}-]/gu, ''))
      .filter((word) => word.length >= 3 && !NOT_NAMES.has(word) && !SMALL_WORDS.has(word)),
  );
  const phrases = [...exact]
    .filter((label) => /^\p{Lu}/u.test(label) && /\s/.test(label) && label.split(/\s+/).length <= LABEL_WORDS_MAX)
    .sort((a, b) => b.length - a.length);
  // Longest first: "Render image" before "Render".
  const anyPhrase = new RegExp(`(?<![\\p{L}\\p{N}])(?:${phrases.map(escape).join('|')})(?![\\p{L}\\p{N}])`, 'gu');
  const firstWords = new Set([...exact, ...items].map((label) => label.split(/\s+/)[0]));
  return { language, exact, patterns, items, labelWords, firstWords, phrases: anyPhrase };
}

/** Whether `name` is written exactly as the screen shows it: a label, or the name of one of the level's objects and lights. */
export function isOnScreen(name: string, words: ScreenWords): boolean {
  return words.exact.has(name) || words.items.includes(name) || words.patterns.some((pattern) => pattern.test(name));
}

/**
 * The names `text` marks that the screen does not show, each with what is wrong as far as
 * the words tell: the same label in other capitals, or the other language's label.
 */
export function namesNotOnScreen(text: string, words: ScreenWords, otherLanguage?: ScreenWords): string[] {
  return markedNames(text)
    .filter((name) => !isOnScreen(name, words))
    .map((name) => {
      const lower = name.toLowerCase();
      const capitals = [...words.exact].find((label) => label.toLowerCase() === lower);
      if (capitals) return `**${name}** (the screen writes "${capitals}")`;
      if (otherLanguage && isOnScreen(name, otherLanguage))
        return `**${name}** (a label of the ${otherLanguage.language === 'en' ? 'English' : 'Dutch'} screen)`;
      return `**${name}** (no label on the ${words.language === 'en' ? 'English' : 'Dutch'} screen reads so)`;
    });
}

/**
 * Cues that a phrase names a panel, a section or a control, by language. `nounAfter`: the
 * name comes right before the noun ("the Shadows switch"); `nounBefore`: right after it
 * ("het paneel Lamp", "de knop Renderen"); `compound`: joined by a hyphen ("de Render-knop");
 * `verbs`: the name follows the word ("press Render", "klik op Beeld renderen"); `places`: so
 * does a name, when the screen has a label that begins with the word after it ("under Lens
 * and shutter", but not "under Lambert's law").
 */
const CUES: Record<Language, { nounAfter: string[]; nounBefore: string[]; compound: string[]; verbs: string[]; places: string[] }> = {
  en: {
    nounAfter: [
      'panel',
      'panels',
      'section',
      'sections',
      'button',
      'buttons',
      'switch',
      'switches',
      'slider',
      'sliders',
      'checkbox',
      'tab',
      'menu',
      'field',
      'fields',
      'heading',
    ],
    nounBefore: [],
    compound: [],
    verbs: [
      'press',
      'presses',
      'pressing',
      'click',
      'clicks',
      'clicking',
      'click on',
      'tap',
      'tap on',
      'open',
      'opens',
      'choose',
      'pick',
      'set',
      'switch',
      'switch on',
      'switch off',
      'turn on',
      'turn off',
      'tick',
      'untick',
    ],
    places: ['under'],
  },
  nl: {
    nounAfter: [],
    nounBefore: [
      'paneel',
      'panelen',
      'sectie',
      'kopje',
      'onderdeel',
      'knop',
      'knoppen',
      'schakelaar',
      'schuif',
      'schuifje',
      'schuifregelaar',
      'vakje',
      'veld',
      'tabblad',
      'menu',
    ],
    compound: ['paneel', 'sectie', 'kopje', 'knop', 'schakelaar', 'schuif', 'schuifje', 'schuifregelaar', 'vakje', 'veld', 'tabblad', 'menu'],
    verbs: ['druk op', 'drukt op', 'klik op', 'klikt op', 'tik op', 'tikt op', 'kies', 'kiest', 'open', 'opent', 'zet', 'vink', 'vinkt'],
    places: ['onder'],
  },
};

/** Keys of the keyboard, which a text names as the key's cap reads ("press P", "druk op Escape"), not as a label. */
const KEYS = new Set(['Escape', 'Esc', 'Enter', 'Return', 'Delete', 'Del', 'Backspace', 'Space', 'Shift', 'Ctrl', 'Control', 'Alt', 'Tab', 'Home', 'End']);

function isKey(word: string): boolean {
  return /^\p{L}\)?$/u.test(word) || KEYS.has(word);
}

/** Stands in for a marked name once it is taken out of the text, so the cues see a name there, and a correct one. */
const MARK = '\u0000';

const WORD = String.raw`[\p{L}\p{N}][\p{L}\p{N}'’()-]*`;

function capitalized(word: string): boolean {
  return /^\p{Lu}/u.test(word);
}

/** Whether the word at `at` begins a sentence, where a capital says nothing about it. */
function startsSentence(text: string, at: number): boolean {
  return /(?:^|[.!?:;]\s+|\n\s*|["“„(]\s*)$/u.test(text.slice(0, at));
}

/**
 * Phrases of `text` that name a panel, section or control without marking the name: "the
 * Ray tracer panel", "press Render", "het paneel Lamp", "onder Lens en sluiter", and any label
 * of the screen in quotation marks. A heuristic: it looks at the words around the cues above,
 * so it can be fooled, but a correctly written text ("the **Shadows** switch", "press
 * **Render**") passes.
 */
export function unmarkedNames(text: string, words: ScreenWords): string[] {
  const cues = CUES[words.language];
  const plain = text.replace(/\*\*[^*\n]+\*\*/g, MARK);
  const found: string[] = [];
  // One phrase is reported once, by the first cue that finds it ("open the Ray tracer panel" is a verb's and a noun's).
  const taken: [number, number][] = [];
  const add = (match: RegExpMatchArray) => {
    const [start, end] = [match.index ?? 0, (match.index ?? 0) + match[0].length];
    if (taken.some(([from, to]) => start < to && from < end)) return;
    taken.push([start, end]);
    if (!found.includes(match[0])) found.push(match[0]);
  };
  // Longest first, so "switch on Show" is read as "switch on" and a name, not as "switch" and "on".
  const alternatives = (list: string[]) =>
    [...list]
      .sort((a, b) => b.length - a.length)
      .map((cue) => cue.replace(/ /g, '\\s+'))
      .join('|');
  if (cues.nounAfter.length > 0) {
    // "the Ray tracer panel", "the tracer panel": a capital, or a word of the screen's labels, right before the noun is a name.
    // A symbol in brackets may stand between them: "the Refractive index (η) slider".
    for (const match of plain.matchAll(new RegExp(`(${WORD})(?:\\s+\\([^()\\s]{1,4}\\))?\\s+(?:${alternatives(cues.nounAfter)})(?![\\p{L}\\p{N}])`, 'giu'))) {
      const word = match[1];
      if (NOT_NAMES.has(word.toLowerCase())) continue;
      if ((capitalized(word) && !startsSentence(plain, match.index)) || words.labelWords.has(word.toLowerCase().replace(/[^\p{L}\p{N}-]/gu, ''))) add(match);
    }
  }
  if (cues.nounBefore.length > 0) {
    // "het paneel Lamp", "de knop Renderen": a capital after the noun starts a name.
    for (const match of plain.matchAll(new RegExp(`(?<![\\p{L}\\p{N}-])(?:${alternatives(cues.nounBefore)})\\s+(${WORD})`, 'giu'))) {
      if (capitalized(match[1])) add(match);
    }
  }
  if (cues.compound.length > 0) {
    // "de Render-knop", "het Lamp-paneel": the part before the hyphen is the name.
    for (const match of plain.matchAll(new RegExp(`(${WORD})-(?:${alternatives(cues.compound)})(?![\\p{L}\\p{N}])`, 'giu'))) {
      add(match);
    }
  }
  // "press Render", "klik op Beeld renderen": a capital after the verb (or after "the"/"de"/"het") starts a name, unless
  // it is a key ("press P") or one of the level's objects and lights ("click the Lamp").
  const article = words.language === 'en' ? '(?:the\\s+)?' : '(?:(?:de|het)\\s+)?';
  for (const match of plain.matchAll(new RegExp(`(?<![\\p{L}\\p{N}])(?:${alternatives(cues.verbs)})\\s+${article}(${WORD})`, 'giu'))) {
    const rest = plain.slice(match.index + match[0].length - match[1].length);
    if (capitalized(match[1]) && !isKey(match[1]) && !words.items.some((item) => rest.startsWith(item))) add(match);
  }
  // "under Lens and shutter", "onder Lens en sluiter": after "under", a capital that begins a label.
  for (const match of plain.matchAll(new RegExp(`(?<![\\p{L}\\p{N}])(?:${alternatives(cues.places)})\\s+${article}(${WORD})`, 'giu'))) {
    if (capitalized(match[1]) && words.firstWords.has(match[1])) add(match);
  }
  // "open Debug a pixel": a label of two words or more, as the screen writes it, is a name inside a sentence (at its start,
  // the capital may be only the sentence's: "Side by side, …").
  for (const match of plain.matchAll(words.phrases)) {
    if (!startsSentence(plain, match.index)) add(match);
  }
  // "Press "Render"": a label of the screen in quotation marks is a name to mark (a quoted line of the debugger's
  // code, in lower case, is not a label).
  for (const match of plain.matchAll(/["“„‘]([^"“”„‘’\n]{1,60})["”“’]/gu)) {
    if (capitalized(match[1]) && isOnScreen(match[1], words)) add(match);
  }
  return found;
}
