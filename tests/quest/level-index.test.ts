import { issueLine } from '../../src/util/issue.ts';
import { describe, expect, it } from 'vitest';
import { readFileSync } from 'node:fs';
import { IDEA_MAX, loadLevelGuide, loadLevels, playableLevels } from '../../src/quest/level-index.ts';
import { catalogOf, levelFile, levelWithId } from '../support/quest-fixtures.ts';

describe('loading the levels of an index', () => {
  it('keeps a broken level in the catalog with its reasons, and the others still play', () => {
    const broken = levelFile((level) => {
      level.id = 'broken-level';
      level.tasks[0].goal = { event: 'view.spun' };
    });
    const catalog = catalogOf([{ id: 'test', levels: [levelWithId('first'), broken, levelWithId('third')] }]);
    const [first, second, third] = catalog.chapters[0].entries;
    expect(first.ok).toBe(true);
    expect(second).toMatchObject({ id: 'broken-level', ok: false });
    expect(!second.ok && issueLine(second.errors[0]!)).toMatch(/^tasks\[0\]\.goal\.event: must be one of/);
    expect(third.ok).toBe(true);
    expect(playableLevels(catalog).map((level) => level.id)).toEqual(['first', 'third']);
  });

  it('reports a missing file, bad JSON, and an id or chapter that differ from the index', () => {
    const index = JSON.stringify({ version: 1, chapters: [{ id: 'test', title: 'Test', levels: ['missing', 'bad-json', 'renamed', 'moved'] }] });
    const files: Record<string, string> = {
      'bad-json.level.json': '{ "version": 1',
      'renamed.level.json': JSON.stringify(levelWithId('old-name')),
      'moved.level.json': JSON.stringify(levelWithId('moved', 'other-chapter')),
    };
    const entries = loadLevels(index, (name) => files[name]).chapters[0].entries;
    expect(entries.map((entry) => (entry.ok ? 'ok' : entry.errors.map(issueLine)))).toEqual([
      ['(root): there is no file levels/missing.level.json'],
      ['(root): not valid JSON at line 1, column 15: expected "," or "}", found the end of the text'],
      ['id: must be "renamed", the name index.json lists this file under, got "old-name"'],
      ['chapter: must be "test", the chapter index.json lists it in, got "other-chapter"'],
    ]);
  });

  it('reports problems of the index itself, and then has no chapters', () => {
    const twice = JSON.stringify({
      version: 1,
      chapters: [
        { id: 'a', title: 'A', levels: ['one'] },
        { id: 'b', title: 'B', levels: ['one'] },
      ],
    });
    expect(loadLevels(twice, () => undefined).errors.map(issueLine)).toEqual(['chapters[1].levels[0]: "one" is used more than once']);
    expect(loadLevels('{"version": 2, "chapters": []}', () => undefined).errors.map(issueLine)).toEqual([
      'version: must be 1, got 2',
      'chapters: must have at least 1 items, got a list of 0 items',
    ]);
  });
});

describe('the ideas and presets of an index, for teachers', () => {
  const index = (extra: Record<string, unknown>) =>
    JSON.stringify({
      version: 1,
      chapters: [
        { id: 'a', title: 'A', levels: ['one', 'two'] },
        { id: 'b', title: 'B', levels: ['three'] },
      ],
      ...extra,
    });
  const idea = { en: 'looking around', nl: 'rondkijken' };
  const preset = { id: 'short', title: 'Short', levels: ['three', 'one'] };

  it("reads each level's idea and the presets; an index without them has none", () => {
    expect(loadLevelGuide(index({ ideas: { one: idea, three: 'mirrors' }, presets: [preset] }))).toEqual({
      ideas: { one: idea, three: 'mirrors' },
      presets: [preset],
    });
    expect(loadLevelGuide(index({}))).toEqual({ ideas: {}, presets: [] });
    expect(loadLevelGuide('{ "version": 1')).toEqual({ ideas: {}, presets: [] });
  });

  it('refuses ideas and presets that name a level no chapter lists, a level twice, a preset id twice, an idea longer than a line', () => {
    const errors = (extra: Record<string, unknown>) => loadLevels(index(extra), () => undefined).errors.map(issueLine);
    expect(errors({ ideas: { one: idea, gone: idea } })).toEqual(['ideas.gone: "gone" is not a level of any chapter']);
    expect(errors({ presets: [{ ...preset, levels: ['one', 'four', 'one'] }] })).toEqual([
      'presets[0].levels[1]: "four" is not a level of any chapter',
      'presets[0].levels[2]: "one" is used more than once',
    ]);
    expect(errors({ presets: [preset, { ...preset, levels: ['two'] }] })).toEqual(['presets[1].id: "short" is used more than once']);
    expect(errors({ presets: [{ ...preset, levels: [] }] })).toEqual(['presets[0].levels: must have at least 1 items, got a list of 0 items']);
    expect(errors({ ideas: { two: { en: 'x'.repeat(IDEA_MAX + 1) } } })).toEqual([`ideas.two.en: must be at most ${IDEA_MAX} characters long`]);
  });
});

describe('levels/index.json for teachers', () => {
  const text = readFileSync(new URL('../../levels/index.json', import.meta.url), 'utf8');
  const listed = (JSON.parse(text) as { chapters: { levels: string[] }[] }).chapters.flatMap((chapter) => chapter.levels);
  const guide = loadLevelGuide(text);

  it('names the one idea of every level, in English and Dutch', () => {
    expect(Object.keys(guide.ideas)).toEqual(listed);
    for (const id of listed) expect(guide.ideas[id], id).toEqual({ en: expect.any(String), nl: expect.any(String) });
  });

  it('has the short path for pupils: levels 1–5, 10, 11 and 14, in that order', () => {
    expect(guide.presets.map((preset) => preset.id)).toEqual(['core-levels']);
    expect(guide.presets[0].levels).toEqual([
      '01-introduction',
      '02-rays-from-the-camera',
      '03-shading',
      '04-shadows',
      '05-reflections',
      '10-area-lights',
      '11-anti-aliasing',
      '14-finding-your-way',
    ]);
  });
});
