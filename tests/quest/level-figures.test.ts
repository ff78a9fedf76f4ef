import { existsSync, readdirSync, readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { parseLevel } from '../../src/quest/level-schema.ts';
import { levelFile } from '../support/quest-fixtures.ts';

/**
 * A task may show a figure above its text (`figure: { src, alt }`, docs/levels.md): a file in
 * assets/figures, which the task card bundles (src/ui/game/figure-urls.ts), with an alt text
 * in the level's languages. Every figure a level names must be there, and must work where the
 * app runs: the build's Content-Security-Policy and the single-file USB build take a figure as
 * a data: URL, so an SVG may load nothing of its own (no script, nothing from elsewhere), and it
 * must scale to the task column (a viewBox).
 */

const FIGURES = new URL('../../assets/figures/', import.meta.url);
const levelsFolder = new URL('../../levels/', import.meta.url);
const levelFiles = readdirSync(levelsFolder).filter((name) => name.endsWith('.level.json'));

const withFigure = (figure: unknown) => parseLevel(levelFile((level) => (level.tasks[0].figure = figure)));

describe('a task’s figure', () => {
  it('is a file name with an alt text in the level’s languages', () => {
    const result = withFigure({ src: 'lambert-torch.svg', alt: { en: 'A torch shines on a card, square and tilted.', nl: 'Een zaklamp schijnt op een kaartje, recht en gekanteld.' } });
    if (!result.ok) throw new Error(result.errors.join('\n'));
    expect(result.level.tasks[0].figure).toEqual({ src: 'lambert-torch.svg', alt: { en: 'A torch shines on a card, square and tilted.', nl: 'Een zaklamp schijnt op een kaartje, recht en gekanteld.' } });
  });

  it('needs its alt text, and a plain file name of an image', () => {
    expect(withFigure({ src: 'lambert-torch.svg' })).toEqual({ ok: false, errors: ['tasks[0].figure.alt: is required'] });
    const named = (src: string) => withFigure({ src, alt: 'A torch.' });
    const problem = (src: string) =>
      `tasks[0].figure.src: must be a file name in assets/figures like "lambert-torch.svg" (lower-case words joined by "-", ending .svg or .png), got "${src}"`;
    expect(named('../secret.svg')).toEqual({ ok: false, errors: [problem('../secret.svg')] });
    expect(named('https://example.com/torch.svg')).toEqual({ ok: false, errors: [problem('https://example.com/torch.svg')] });
    expect(named('Torch.SVG')).toEqual({ ok: false, errors: [problem('Torch.SVG')] });
    // SVG and PNG only: the offline cache (vite.config.ts, workbox) keeps those kinds of file.
    expect(named('torch.jpg')).toEqual({ ok: false, errors: [problem('torch.jpg')] });
    expect(named('torch-2.png').ok).toBe(true);
  });
});

describe('the figures in assets/figures', () => {
  const svgs = readdirSync(FIGURES).filter((name) => name.endsWith('.svg'));

  it.each(svgs)('%s scales to the column and loads nothing of its own', (name) => {
    const svg = readFileSync(new URL(name, FIGURES), 'utf8');
    expect(svg).toMatch(/<svg [^>]*viewBox="[\d. ]+"/);
    expect(svg).not.toMatch(/<script|<foreignObject|\son\w+=/i);
    // Only references inside the file itself (#id): a data: URL has nothing beside it to load.
    expect([...svg.matchAll(/(?:href|src)="([^"]*)"|url\(([^)]*)\)/g)].map((match) => match[1] ?? match[2]).filter((target) => !target.startsWith('#'))).toEqual([]);
  });
});

describe('level files', () => {
  it.each(levelFiles)('%s shows only figures that are in assets/figures', (file) => {
    const level = JSON.parse(readFileSync(new URL(file, levelsFolder), 'utf8')) as { tasks?: { id?: string; figure?: { src?: unknown } }[] };
    const missing = (level.tasks ?? [])
      .filter((task) => task.figure !== undefined)
      .filter((task) => typeof task.figure?.src !== 'string' || !existsSync(new URL(task.figure.src, FIGURES)))
      .map((task) => `${task.id}: ${String(task.figure?.src)}`);
    expect(missing).toEqual([]);
  });
});
