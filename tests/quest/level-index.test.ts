import { describe, expect, it } from 'vitest';
import { loadLevels, playableLevels } from '../../src/quest/level-index.ts';
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
    expect(!second.ok && second.errors[0]).toMatch(/^tasks\[0\]\.goal\.event: must be one of/);
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
    expect(entries.map((entry) => (entry.ok ? 'ok' : entry.errors))).toEqual([
      ['(root): there is no file levels/missing.level.json'],
      ['(root): not valid JSON at line 1, column 15: expected "," or "}", found the end of the text'],
      ['id: must be "renamed", the name index.json lists this file under, got "old-name"'],
      ['chapter: must be "test", the chapter index.json lists it in, got "other-chapter"'],
    ]);
  });

  it('reports problems of the index itself, and then has no chapters', () => {
    const twice = JSON.stringify({ version: 1, chapters: [{ id: 'a', title: 'A', levels: ['one'] }, { id: 'b', title: 'B', levels: ['one'] }] });
    expect(loadLevels(twice, () => undefined)).toEqual({ chapters: [], errors: ['chapters[1].levels[0]: "one" is used more than once'] });
    expect(loadLevels('{"version": 2, "chapters": []}', () => undefined).errors).toEqual([
      'version: must be 1, got 2',
      'chapters: must have at least 1 items, got a list of 0 items',
    ]);
  });
});
