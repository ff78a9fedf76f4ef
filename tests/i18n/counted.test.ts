// A count is said with the noun's singular for exactly one, in English and Dutch: the screen
// reader once read "1 lampen" for the 3D view of a level with one lamp (issue 37).
import { readdirSync, readFileSync, statSync } from 'node:fs';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';
import { answersCounted, bvhBoxesCounted, studentsCounted, lightsCounted, objectsCounted, pointsCounted, trianglesCounted } from '../../src/i18n/counted.ts';
import { surveyDamageText } from '../../src/i18n/progress-problem-text.ts';
import { inDutch } from '../support/page-locale.ts';

const COUNTERS = {
  objects: objectsCounted,
  lights: lightsCounted,
  learners: studentsCounted,
  answers: answersCounted,
  points: pointsCounted,
  boxes: (n: number) => bvhBoxesCounted(n, String(n)),
  triangles: (n: number) => trianglesCounted(n, String(n)),
};

function says(words: Record<keyof typeof COUNTERS, [one: string, many: string]>): void {
  for (const [name, counted] of Object.entries(COUNTERS) as [keyof typeof COUNTERS, (n: number) => string][]) {
    const [one, many] = words[name];
    it(`counts ${name}: ${one}, ${many}`, () => {
      expect(counted(1)).toBe(`1 ${one}`);
      for (const n of [0, 2, 12]) expect(counted(n)).toBe(`${n} ${many}`);
    });
  }
}

describe('counts in English', () => {
  says({
    objects: ['object', 'objects'],
    lights: ['light', 'lights'],
    learners: ['student', 'students'],
    answers: ['answer', 'answers'],
    points: ['point', 'points'],
    boxes: ['BVH box', 'BVH boxes'],
    triangles: ['triangle', 'triangles'],
  });
  it('says one kept survey answer as one', () => {
    expect(surveyDamageText({ askedAgain: false, kept: 1, leftOut: null, backedUp: false })).toContain('(1 answer)');
  });
});

describe('counts in Dutch', () => {
  inDutch();
  says({
    objects: ['object', 'objecten'],
    lights: ['lamp', 'lampen'],
    learners: ['leerling', 'leerlingen'],
    answers: ['antwoord', 'antwoorden'],
    points: ['punt', 'punten'],
    boxes: ['BVH-doos', 'BVH-dozen'],
    triangles: ['driehoek', 'driehoeken'],
  });
  it('says one kept survey answer as one', () => {
    expect(surveyDamageText({ askedAgain: false, kept: 1, leftOut: null, backedUp: false })).toContain('(1 antwoord)');
  });
});

const SRC = fileURLToPath(new URL('../../src', import.meta.url));
const sources = (folder: string): string[] =>
  readdirSync(folder).flatMap((name) => {
    const path = join(folder, name);
    return statSync(path).isDirectory() ? sources(path) : name.endsWith('.ts') && !path.includes('/locales/') ? [path] : [];
  });

describe('every count of these nouns goes through a singular', () => {
  // "${n} lights" in a message is the plural branch of a `=== 1 ?` (counted.ts), or a part
  // such as "of ${total} learners" that is never one thing alone, or a constant (STUCK_MIN_LEARNERS) that is more than one.
  const BARE_COUNT = /(?<!of |all )\$\{(?![A-Z_]+\})[^}]*\} (objects|lights|learners|students|answers|triangles|BVH boxes)\b/;
  it('has no bare count left in src', () => {
    const bare = sources(SRC).flatMap((path) => {
      const lines = readFileSync(path, 'utf8').split('\n');
      return lines.flatMap((line, index) =>
        BARE_COUNT.test(line) && !/=== 1\s*\?/.test(lines.slice(Math.max(0, index - 4), index + 1).join('\n')) ? [`${path}:${index + 1}: ${line.trim()}`] : [],
      );
    });
    expect(bare).toEqual([]);
  });
});
