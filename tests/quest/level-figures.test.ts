import { issueLine } from '../../src/util/issue.ts';
import { readdirSync, readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { FIGURE_FILES } from '../../src/quest/figure-files.ts';
import { parseLevel } from '../../src/quest/level-schema.ts';
import { levelFile } from '../support/quest-fixtures.ts';

/**
 * A task may show a figure above its text (`figure: { src, alt }`, docs/levels.md): one of the
 * files in assets/figures, which the task card bundles (src/ui/game/figure-urls.ts), with an
 * alt text in the level's languages. A level that names a figure the app does not ship is
 * refused when it loads. Every figure must work where the app runs: the build's
 * Content-Security-Policy and the single-file USB build take a figure as a data: URL, so an
 * SVG may load nothing of its own (no script, nothing from elsewhere), and it must scale to the
 * task column (a viewBox).
 */

const FIGURES = new URL('../../assets/figures/', import.meta.url);
const ALT = { en: 'A torch shines on a card, square and tilted.', nl: 'Een zaklamp schijnt op een kaartje, recht en gekanteld.' };

const withFigure = (figure: unknown) => parseLevel(levelFile((level) => (level.tasks[0].figure = figure)));

describe('a task’s figure', () => {
  it('is a shipped figure with an alt text in the level’s languages', () => {
    const result = withFigure({ src: 'lambert-torch.svg', alt: ALT });
    if (!result.ok) throw new Error(result.errors.map(issueLine).join('\n'));
    expect(result.level.tasks[0].figure).toEqual({ src: 'lambert-torch.svg', alt: ALT });
  });

  it('needs its alt text, and a figure the app ships', () => {
    expect(withFigure({ src: 'lambert-torch.svg' })).toEqual({ ok: false, errors: [{ path: 'tasks[0].figure.alt', reason: { code: 'required' } }] });
    // The reason lists the figures there are ("must be "lambert-torch.svg"" while it is the only one).
    const refused = (src: string) => {
      const result = withFigure({ src, alt: ALT });
      return result.ok ? [] : result.errors.map(issueLine);
    };
    expect(refused('torch.svg')).toEqual([expect.stringMatching(/^tasks\[0\]\.figure\.src: must be .*"?lambert-torch\.svg"?.*, got "torch\.svg"$/)]);
    expect(refused('../levels/index.json')).toEqual([
      expect.stringMatching(/^tasks\[0\]\.figure\.src: must be .*lambert-torch\.svg.*, got "\.\.\/levels\/index\.json"$/),
    ]);
  });
});

describe('the figures in assets/figures', () => {
  it('are the ones the level schema knows, each an SVG or a PNG (the kinds the offline cache keeps)', () => {
    expect(readdirSync(FIGURES).sort()).toEqual([...FIGURE_FILES].sort());
    expect(FIGURE_FILES.filter((name) => !/^[a-z0-9]+(?:-[a-z0-9]+)*\.(?:svg|png)$/.test(name))).toEqual([]);
  });

  it.each(FIGURE_FILES.filter((name) => name.endsWith('.svg')))('%s scales to the column and loads nothing of its own', (name) => {
    const svg = readFileSync(new URL(name, FIGURES), 'utf8');
    expect(svg).toMatch(/<svg [^>]*viewBox="[\d. ]+"/);
    expect(svg).not.toMatch(/<script|<foreignObject|\son\w+=/i);
    // Only references inside the file itself (#id): a data: URL has nothing beside it to load.
    expect(
      [...svg.matchAll(/(?:href|src)="([^"]*)"|url\(([^)]*)\)/g)].map((match) => match[1] ?? match[2]).filter((target) => !target.startsWith('#')),
    ).toEqual([]);
  });
});
