import { readFileSync } from 'node:fs';

/** The seeded random as public/code-lab-sandbox.html defines it (its source, run here): the numbers a learner's function gets for { seededRandom }. */
export const sandboxRandomSource = /const seededRandom = \(seed\) => \{[\s\S]*?\n {2}\};\n/.exec(
  readFileSync(new URL('../../public/code-lab-sandbox.html', import.meta.url), 'utf8'),
)?.[0];

if (!sandboxRandomSource) throw new Error('public/code-lab-sandbox.html defines no seededRandom');

export const sandboxSeededRandom = new Function(`${sandboxRandomSource}; return seededRandom;`)() as (seed: number) => () => number;
