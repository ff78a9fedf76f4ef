// The code labs' numbers as the reader's language writes them: a Dutch pupil reads "0.5" as a
// typo and "8,624" as eight and a bit, so the Dutch reports write "p = 0,000013" and vectors as
// "(0,5; 1; 2)", as the rest of the app does (src/i18n/number-format.ts).
import type { TemplateResult } from 'lit';
import { afterAll, beforeAll, describe, expect, it, vi } from 'vitest';
import type { LabCase } from '../../../../src/quest/code-labs/code-lab-grading.ts';
import type { DirectionReport, DirectionRun, DirectionTest } from '../../../../src/quest/code-labs/direction-statistics.ts';
import type { StatisticsReport } from '../../../../src/quest/code-labs/code-lab-statistics.ts';
import * as statistics from '../../../../src/ui/game/code-lab/code-lab-statistics-report.ts';
import * as texts from '../../../../src/ui/game/code-lab/code-lab-texts.ts';
import * as direction from '../../../../src/ui/game/code-lab/direction-statistics-report.ts';
import * as numbers from '../../../../src/ui/game/code-lab/lab-numbers.ts';
import { standInPage } from '../../../support/page-locale.ts';

/** The words of a lit template, its parts and its values in order (the panel's text without a browser). */
function words(value: unknown): string {
  if (Array.isArray(value)) return value.map(words).join('');
  if (typeof value === 'object' && value !== null && 'strings' in value) {
    const { strings, values } = value as TemplateResult;
    return strings.map((part, index) => part + (index < values.length ? words(values[index]) : '')).join('');
  }
  return typeof value === 'string' || typeof value === 'number' ? String(value) : '';
}

const oneLine = (text: string) => text.replace(/\s+/g, ' ').trim();

const uneven: DirectionTest = { normal: 'normal-plus-z', measure: 'cos-theta', bins: 10, value: 41.25, degrees: 9, p: 0.0000131 };
const unevenReport: DirectionReport = {
  runs: 4,
  passedRuns: 4,
  directions: [],
  tests: [uneven],
  significance: 0.00125,
  firstFailure: { check: 'uneven-cos-theta', test: uneven },
};
const runs: DirectionRun[] = [{ kind: 'normal-plus-z', args: [{ x: 0, y: 0, z: 1 }, { seededRandom: 1 }] }];
const tooLong: DirectionReport = {
  runs: 1,
  passedRuns: 0,
  directions: [],
  tests: [],
  significance: 0.00125,
  firstFailure: { check: 'not-unit', run: 0, direction: { x: 0.5, y: 0.25, z: 1.5 }, length: 1.6007810593 },
};
const samples: StatisticsReport = {
  runs: 12,
  passedRuns: 12,
  points: 300,
  test: { value: 3.5, degrees: 15, p: 0.25, significance: 0.001, bins: 16 },
  firstFailure: null,
};
const sphereCase: LabCase = { kind: 'hit-from-outside', args: [{ x: 0, y: 0, z: -5 }, { x: 0, y: 0.6, z: 0.8 }, { x: 0, y: 0, z: 0 }, 1.5], expected: 3.25 };

describe('the code labs’ numbers', () => {
  let speak: (locale: 'en' | 'nl') => Promise<void>;

  beforeAll(async () => {
    speak = await standInPage();
  });

  afterAll(async () => {
    await speak('en');
    vi.unstubAllGlobals();
  });

  it('spells out values with a decimal point in English', async () => {
    await speak('en');
    expect(numbers.labValue({ x: 1 / 3, y: 0, z: -2 })).toBe('(0.333333, 0, -2)');
    expect(numbers.labValue({ r: 1, g: 0.5, b: 0 })).toBe('(1, 0.5, 0)');
    expect(numbers.labValue({ x: 1, y: 2, z: NaN })).toBe('(1, 2, NaN)');
    expect(numbers.labValue(12345.678)).toBe('12345.7');
    expect([numbers.labValue({}), numbers.labValue([1]), numbers.labValue(null), numbers.labValue('5')]).toEqual(['object', 'array', 'null', '"5"']);
    expect(oneLine(words(direction.directionReport(unevenReport, runs)))).toContain(
      'χ² of cos θ = 41.3 with 9 degrees of freedom, p = 0.000013 (below 0.0013 fails).',
    );
    // Every run passed its own checks: the report says that only the test over all of them failed.
    expect(oneLine(words(direction.directionReport(unevenReport, runs)))).toContain('All 4 runs pass one by one; together they fail a χ² test.');
    expect(oneLine(words(direction.directionReport(tooLong, runs)))).toContain('0 of 1 runs pass.');
  });

  it('writes a decimal comma in Dutch, and separates a vector’s numbers with semicolons', async () => {
    await speak('nl');
    expect(numbers.labValue({ x: 1 / 3, y: 0, z: -2 })).toBe('(0,333333; 0; -2)');
    expect(numbers.labValue(12345.678)).toBe('12345,7');
    expect(numbers.labValue({ x: 1, y: 2, z: Infinity })).toBe('(1; 2; Infinity)');

    // The kinds of case that name a vector write it as the values beside them are written.
    expect([texts.caseKindName('normal-plus-z'), texts.caseKindName('off-centre')]).toEqual([
      'de normaal (0; 0; 1)',
      'een bol met zijn middelpunt niet in (0; 0; 0)',
    ]);

    const cosine = oneLine(words(direction.directionReport(unevenReport, runs)));
    expect(cosine).toContain('= 41,3 met 9 vrijheidsgraden, p = 0,000013 (onder 0,0013 ');
    expect(cosine).toContain('Alle 4 runs zijn elk op zich goed; samen zakken ze voor een χ²-toets.');
    const length = oneLine(words(direction.directionReport(tooLong, runs)));
    expect(length).toContain('(0,5; 0,25; 1,5)');
    expect(length).toContain('1,60078');

    const sampled = oneLine(words(statistics.statisticsReport(samples, [])));
    expect(sampled).toContain('χ² = 3,5');
    expect(sampled).toContain('p = 0,25');
    expect(sampled).toContain('0,001');

    expect(texts.caseInput('hitSphere(origin, direction, centre, radius)', sphereCase.args)).toBe(
      'origin (0; 0; -5), direction (0; 0,6; 0,8), centre (0; 0; 0), radius 1,5',
    );
    const failure = { index: 0, labCase: sphereCase, reason: 'wrong-value' as const, got: 2.5, gotValue: 2.5 };
    expect(texts.failureText(failure, 'ray-sphere', { answer: 'number', relative: 1e-6 })).toMatch(/t = 3,25.*t = 2,5/);

    // No number in these reports keeps JavaScript's decimal point.
    for (const text of [cosine, length, sampled]) expect(text).not.toMatch(/\d\.\d/);
  });
});
