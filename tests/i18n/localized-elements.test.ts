// Every element of the app renders again when the language changes, by itself: it derives from
// LocalizedElement (src/ui/controls/localized-element.ts), whose constructor asks @lit/localize
// for it (updateWhenLocaleChanges). Read from the sources: each class registered with
// customElements.define is followed up its `extends` chain.
import { readdirSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';

const SRC = new URL('../../src/', import.meta.url).pathname;

function sourceFiles(folder: string): string[] {
  return readdirSync(folder, { withFileTypes: true }).flatMap((entry) => {
    const path = join(folder, entry.name);
    if (entry.isDirectory()) return sourceFiles(path);
    return entry.name.endsWith('.ts') ? [path] : [];
  });
}

const sources = sourceFiles(SRC).map((path) => ({ path: path.slice(SRC.length), text: readFileSync(path, 'utf8') }));

/** Each class of the sources and the class it extends. */
const parents = new Map<string, string>();
for (const { text } of sources) {
  for (const match of text.matchAll(/\bclass (\w+)(?:<[^{]*?>)? extends (\w+)/g)) parents.set(match[1]!, match[2]!);
}

/** The classes up a class's `extends` chain, itself first. */
function chain(name: string): string[] {
  const names = [name];
  for (let parent = parents.get(name); parent !== undefined && !names.includes(parent); parent = parents.get(parent)) names.push(parent);
  return names;
}

describe('elements and the language', () => {
  const registered = sources.flatMap(({ path, text }) =>
    [...text.matchAll(/customElements\.define\('([\w-]+)', (\w+)\)/g)].map((match) => ({ path, tag: match[1]!, name: match[2]! })),
  );

  it('finds the elements the app registers', () => {
    expect(registered.length).toBeGreaterThan(40);
    expect(registered.map(({ tag }) => tag)).toContain('rt-lab');
  });

  it('has every registered element derive from LocalizedElement', () => {
    const missing = registered
      .filter(({ name }) => !chain(name).includes('LocalizedElement'))
      .map(({ path, tag, name }) => `${path}: ${tag} (${chain(name).join(' < ')})`);
    expect(missing).toEqual([]);
  });

  it('has only LocalizedElement extend LitElement, and it asks to render on a language change', () => {
    const direct = [...parents].filter(([, parent]) => parent === 'LitElement').map(([name]) => name);
    expect(direct).toEqual(['LocalizedElement']);
    const base = sources.find(({ path }) => path === 'ui/controls/localized-element.ts')!.text;
    expect(base).toMatch(/constructor\(\) \{\s*super\(\);\s*updateWhenLocaleChanges\(this\);\s*\}/);
  });
});
