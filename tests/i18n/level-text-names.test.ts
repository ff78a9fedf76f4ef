import { readdirSync, readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { hasStrayMark } from '../../src/quest/text-markup.ts';
import { readDutchCatalogue } from '../support/dutch-catalogue.ts';
import { levelTexts, sceneNames } from '../support/level-texts.ts';
import { namesNotOnScreen, screenWords, unmarkedNames, type ScreenWords } from '../support/ui-labels.ts';

/**
 * A level's texts name what the screen shows (issue 36): every on-screen name is marked,
 * `**Lens and shutter**`, and reads exactly as the screen labels it in the text's language —
 * the English text as the English UI (the `msg()` sources), the Dutch text as the Dutch UI
 * (their targets in xliff/nl.xlf). A name the level's scene gives an object or a light counts
 * too. A second check looks for names left unmarked: "the Ray tracer panel", "press Render",
 * "het paneel Lamp", "onder Lens en sluiter".
 */

const catalogue = readDutchCatalogue();
const english = screenWords(catalogue, 'en');
const dutch = screenWords(catalogue, 'nl');

/**
 * What is wrong with the names in one text, in the words of the screen it is read on. A
 * title is shown without its marks (src/quest/text-markup.ts) and is often the very words of
 * a control ("Zoom in"), so only its marked names are checked.
 */
function problems(path: string, text: string, words: ScreenWords, other: ScreenWords): string[] {
  const unmarked = /(?:^|\.)title$/.test(path) ? [] : unmarkedNames(text, words);
  return [
    ...(hasStrayMark(text) ? ['a ** without its partner'] : []),
    ...namesNotOnScreen(text, words, other),
    ...unmarked.map((phrase) => `"${phrase}" names something on screen without **`),
  ];
}

/** Every problem with the names in a level file's texts, as `path.language: problem`. */
function levelNameProblems(level: unknown): string[] {
  const en = screenWords(catalogue, 'en', sceneNames(level, 'en'));
  const nl = screenWords(catalogue, 'nl', sceneNames(level, 'nl'));
  return levelTexts(level).flatMap(({ path, text }) => {
    const texts = typeof text === 'string' ? { en: text } : text;
    return [
      ...problems(path, texts.en, en, nl).map((problem) => `${path}.en: ${problem}`),
      ...(texts.nl === undefined ? [] : problems(path, texts.nl, nl, en).map((problem) => `${path}.nl: ${problem}`)),
    ];
  });
}

describe('the words of the screen', () => {
  it('hold the panels’ section headings, the toolbar’s and the render window’s buttons, in both languages', () => {
    for (const label of [
      'Lens and shutter',
      'Ray tracer',
      'Anti-aliasing',
      'Ray colours',
      'Save and share',
      'Render image',
      'Render',
      'Time samples (k)',
      'Samples per side (n)',
    ]) {
      expect(english.exact, label).toContain(label);
    }
    for (const label of ['Lens en sluiter', 'Kleuren van de stralen', 'Opslaan en delen', 'Beeld renderen', 'Renderen', 'Tijdsamples (k)']) {
      expect(dutch.exact, label).toContain(label);
    }
    expect(english.exact).not.toContain('Lens en sluiter');
    expect(dutch.exact).not.toContain('Lens and shutter');
  });
});

describe('a marked name', () => {
  it('passes when it is a label of the screen in the text’s language', () => {
    expect(namesNotOnScreen('Set **Time samples (k)** under **Lens and shutter** to 4.', english)).toEqual([]);
    expect(namesNotOnScreen('Zet **Tijdsamples (k)** onder **Lens en sluiter** op 4.', dutch)).toEqual([]);
    // "Badges earned:" is on screen with its colon; the name is the words.
    expect(namesNotOnScreen('Look under **Badges earned**.', english)).toEqual([]);
  });

  it('passes when it fills a label with a placeholder, and fails when the label’s own words differ', () => {
    expect(namesNotOnScreen('Press **Focus on Ball**.', english)).toEqual([]);
    expect(namesNotOnScreen('Druk op **Stel scherp op Bal**.', dutch)).toEqual([]);
    expect(namesNotOnScreen('It reads **3 × 3 = 9 rays per pixel**.', english)).toEqual([]);
    expect(namesNotOnScreen('It reads **3 × 3 = 9 beams per pixel**.', english)).toEqual([
      '**3 × 3 = 9 beams per pixel** (no label on the English screen reads so)',
    ]);
  });

  it('fails when no label reads so, saying what the screen writes where it can tell', () => {
    expect(namesNotOnScreen('Open the **Ray tracer panel**.', english)).toEqual(['**Ray tracer panel** (no label on the English screen reads so)']);
    expect(namesNotOnScreen('Switch **shadows** off.', english)).toEqual(['**shadows** (the screen writes "Shadows")']);
    expect(namesNotOnScreen('Zet **Time samples (k)** op 4.', dutch, english)).toEqual(['**Time samples (k)** (a label of the English screen)']);
    expect(namesNotOnScreen('Set **Tijdsamples (k)** to 4.', english, dutch)).toEqual(['**Tijdsamples (k)** (a label of the Dutch screen)']);
  });

  it('may be one of the level’s own objects and lights, by the name its scene gives it in that language', () => {
    const scene = { scene: { objects: [{ name: { en: 'Red ball', nl: 'Rode bal' } }], lights: [{ name: 'Lamp' }] } };
    expect(namesNotOnScreen('Select **Red ball** and **Lamp**.', screenWords(catalogue, 'en', sceneNames(scene, 'en')))).toEqual([]);
    expect(namesNotOnScreen('Kies **Rode bal**.', screenWords(catalogue, 'nl', sceneNames(scene, 'nl')))).toEqual([]);
    expect(namesNotOnScreen('Kies **Red ball**.', screenWords(catalogue, 'nl', sceneNames(scene, 'nl')))).toHaveLength(1);
  });
});

describe('a name left unmarked', () => {
  it('is found before an English noun of the screen, capitalised or a word of a label', () => {
    expect(unmarkedNames('Look in the Ray tracer panel.', english)).toEqual(['tracer panel']);
    expect(unmarkedNames('The slider is in the object panel.', english)).toEqual(['object panel']);
    expect(unmarkedNames('Move the Refractive index (η) slider.', english)).toEqual(['index (η) slider']);
    expect(unmarkedNames('Use the Pan buttons.', english)).toEqual(['Pan buttons']);
  });

  it('is found after an English verb or "under", and in quotation marks', () => {
    expect(unmarkedNames('Press Render, then look under Lens and shutter.', english)).toEqual(['Press Render', 'under Lens']);
    expect(unmarkedNames('Switch on Show sample points.', english)).toEqual(['Switch on Show']);
    expect(unmarkedNames('Press "Render image".', english)).toEqual(['"Render image"']);
  });

  it('is found after a Dutch noun, before a Dutch compound noun, after a Dutch verb or "onder"', () => {
    expect(unmarkedNames('De schuif staat in het paneel Lamp.', dutch)).toEqual(['paneel Lamp']);
    expect(unmarkedNames('Druk op de Render-knop.', dutch)).toEqual(['Render-knop']);
    expect(unmarkedNames('Zet Tijdsamples (k) onder Lens en sluiter op 4.', dutch)).toEqual(['Zet Tijdsamples', 'onder Lens']);
    expect(unmarkedNames('Druk op Beeld renderen.', dutch)).toEqual(['Druk op Beeld']);
    expect(unmarkedNames('Druk op „Renderen”.', dutch)).toEqual(['„Renderen”']);
  });

  it('is not found in a text that marks its names', () => {
    expect(unmarkedNames('Set **Time samples (k)** under **Lens and shutter** to 4, then press **Render**.', english)).toEqual([]);
    expect(unmarkedNames('Switch on **Show sample points** in the **Anti-aliasing** section; the **Shadows** switch stays on.', english)).toEqual([]);
    expect(unmarkedNames('Zet **Tijdsamples (k)** onder **Lens en sluiter** op 4 en druk op **Renderen**.', dutch)).toEqual([]);
    expect(unmarkedNames('Het paneel **Lamp** heeft een **Render**-knop; de schakelaar **Schaduwen** staat aan.', dutch)).toEqual([]);
  });

  it('is not a key, a word that names nothing, a sentence’s first word, or one of the level’s objects and lights', () => {
    expect(unmarkedNames('Press P, or press Escape to go back.', english)).toEqual([]);
    expect(unmarkedNames('Druk op P of op Escape.', dutch)).toEqual([]);
    expect(unmarkedNames('Drag with the left mouse button. The same panel has a second slider. Then switch shadows off.', english)).toEqual([]);
    expect(unmarkedNames('Its panel shows the roughness. You switch shadows off.', english)).toEqual([]);
    expect(unmarkedNames('Klik op de bal onder de lamp, of open de deur.', dutch)).toEqual([]);
    expect(unmarkedNames('The area light is a glowing panel.', english)).toEqual([]);
    const withLamp = screenWords(catalogue, 'en', ['Lamp']);
    expect(unmarkedNames('Click the Lamp.', withLamp)).toEqual([]);
    // A line of the debugger's code in quotation marks is quoted code, not a label.
    expect(unmarkedNames('The last line, "return clamp(colour, 0, 1)", clamps it.', english)).toEqual([]);
  });
});

const levelsFolder = new URL('../../levels/', import.meta.url);
const levelFiles = readdirSync(levelsFolder).filter((name) => name.endsWith('.level.json'));

describe('level texts', () => {
  it('are found in every part of a level a learner reads', () => {
    const texts = levelTexts({
      title: 'T',
      intro: { text: { en: 'I', nl: 'I' } },
      scene: { name: { en: 'not a text' } },
      tasks: [
        {
          text: 'X',
          hints: ['H'],
          figure: { src: 'a.svg', alt: 'A' },
          goal: { quiz: { question: 'Q', choices: ['1', { en: '2' }], explanation: 'E' } },
          solution: [{ changes: { name: { en: 'no' } } }],
        },
      ],
    });
    expect(texts.map((text) => text.path)).toEqual([
      'title',
      'intro.text',
      'tasks[0].text',
      'tasks[0].hints[0]',
      'tasks[0].figure.alt',
      'tasks[0].goal.quiz.question',
      'tasks[0].goal.quiz.choices[0]',
      'tasks[0].goal.quiz.choices[1]',
      'tasks[0].goal.quiz.explanation',
    ]);
  });

  it('pass in a level that marks its names as each screen writes them, and fail at each slip', () => {
    const written = (hint: { en: string; nl: string }) => ({
      title: { en: 'Zoom in', nl: 'Inzoomen' },
      intro: { text: { en: 'The **Lens and shutter** section has a slider for time.', nl: 'Het kopje **Lens en sluiter** heeft een schuif voor de tijd.' } },
      tasks: [
        {
          title: 'Moments',
          text: { en: 'Set **Time samples (k)** under **Lens and shutter** to 4.', nl: 'Zet **Tijdsamples (k)** onder **Lens en sluiter** op 4.' },
          hints: [hint],
        },
      ],
    });
    expect(
      levelNameProblems(
        written({ en: 'Press **Render image** at the top, then **Render**.', nl: 'Druk bovenaan op **Beeld renderen** en dan op **Renderen**.' }),
      ),
    ).toEqual([]);
    expect(
      levelNameProblems(written({ en: 'Press **Render image** at the top, then press Render.', nl: 'Druk bovenaan op **Render image**, dan op **Renderen.' })),
    ).toEqual([
      'tasks[0].hints[0].en: "press Render" names something on screen without **',
      'tasks[0].hints[0].nl: a ** without its partner',
      'tasks[0].hints[0].nl: **Render image** (a label of the English screen)',
    ]);
  });

  it.each(levelFiles)('%s marks every on-screen name, as the screen writes it in the text’s language', (file) => {
    const level: unknown = JSON.parse(readFileSync(new URL(file, levelsFolder), 'utf8'));
    expect(levelNameProblems(level)).toEqual([]);
  });
});
