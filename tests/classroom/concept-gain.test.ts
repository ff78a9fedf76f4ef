import { describe, expect, it } from 'vitest';
import type { Assignment } from '../../src/classroom/assignment.ts';
import type { ConceptTestAnswers } from '../../src/classroom/concept-test/concept-answers.ts';
import { parseConceptBank, type ConceptBank } from '../../src/classroom/concept-test/concept-bank-schema.ts';
import { conceptGains, normalizedGain } from '../../src/classroom/concept-test/concept-gain.ts';
import { readClassFiles } from '../../src/classroom/dashboard-class.ts';
import { classLearners } from '../../src/classroom/dashboard-learners.ts';
import type { ExportInput } from '../../src/classroom/export-context.ts';
import { exportCsv } from '../../src/classroom/export-csv.ts';
import { exportJson } from '../../src/classroom/export-json.ts';
import { newProgress } from '../../src/quest/progress.ts';
import { CLASS_ASSIGNMENT, simulatedExport } from '../support/class-exports.ts';
import fixture from './fixtures/concept-bank.fixture.json';

/**
 * Hake's gain on the dashboard, from the files a class hands in: learners' JSON and CSV
 * exports (one of them also exported before the test after), read and merged as the
 * dashboard does, give per class and concept the figures worked out by hand below.
 *
 * The fixture bank: form A has shadows-1a, shadows-2a (shadows) and refraction-1a
 * (refraction); form B their twins; every item's answer is the choice "right".
 */

const parsed = parseConceptBank(fixture);
if (!parsed.ok) throw new Error(parsed.errors.join('\n'));
const bank: ConceptBank = parsed.bank;

const assignment = (classCode: string): Assignment => ({ ...CLASS_ASSIGNMENT, classCode, conceptTest: 'counterbalanced' });
const at = '2026-03-09T10:00:00.000Z';
const a = (s1: string, s2: string, r1: string) => ({
  form: 'A' as const,
  submittedAt: at,
  answers: { 'shadows-1a': s1, 'shadows-2a': s2, 'refraction-1a': r1 },
});
const b = (s1: string, s2: string, r1: string) => ({
  form: 'B' as const,
  submittedAt: at,
  answers: { 'shadows-1b': s1, 'shadows-2b': s2, 'refraction-1b': r1 },
});

function input(index: number, classCode: string, conceptTest: ConceptTestAnswers): ExportInput {
  const file = simulatedExport(index);
  const clock = { monotonicMs: () => 0, wallMs: () => Date.parse(file.events.startedAt) };
  return {
    progress: { ...newProgress(clock), log: file.events },
    participant: `P-${index}`,
    installId: `install-${index}`,
    attemptId: `attempt-${index}`,
    assignment: assignment(classCode),
    survey: null,
    conceptTest,
    exportedAt: at,
    appVersion: 'test',
  };
}

// Class 5H2. L1 (A then B): before 1 of 2 shadows right, refraction wrong; after 1 of 2 shadows, refraction right.
const l1 = input(1, '5H2', { pre: a('right', 'wrong', 'wrong'), post: b('right', 'wrong', 'right') });
// L2 (B first): before no shadows, refraction right; after both shadows, refraction wrong.
const l2 = input(2, '5H2', { pre: b('wrong', 'other', 'right'), post: a('right', 'right', 'other') });
// L3 took only the test before: not in n.
const l3 = input(3, '5H2', { pre: a('right', 'right', 'right'), post: null });
// Class 5H3. L4: all right before (nothing left to gain), after 1 of 2 shadows and refraction right.
const l4 = input(4, '5H3', { pre: a('right', 'right', 'right'), post: b('wrong', 'right', 'right') });

const files = [
  { name: 'l1.json', text: exportJson(l1) },
  { name: 'l2.csv', text: exportCsv(l2) },
  { name: 'l3.json', text: exportJson(l3) },
  // L4 pressed "download" after the test before, and again at the end as CSV.
  { name: 'l4-early.json', text: exportJson({ ...l4, conceptTest: { pre: l4.conceptTest!.pre, post: null } }) },
  { name: 'l4.csv', text: exportCsv(l4) },
];

describe("Hake's normalized gain from a class's files", () => {
  const { records, skipped } = readClassFiles(files);
  const learners = classLearners(records);
  const gains = conceptGains(learners, bank);
  const row = (classCode: string, concept: string | null) => gains.find((group) => group.classCode === classCode)?.rows.find((r) => r.concept === concept);

  it('reads every file and counts each learner once', () => {
    expect(skipped).toEqual([]);
    expect(learners).toHaveLength(4);
    expect(gains.map((group) => [group.classCode, group.preOnly, group.postOnly])).toEqual([
      ['5H2', 1, 0],
      ['5H3', 0, 0],
    ]);
  });

  it('gives class 5H2 the figures computed by hand, over the two learners with both tests', () => {
    // Whole test: before (1/3 + 1/3) / 2 = 1/3, after (2/3 + 2/3) / 2 = 2/3, ⟨g⟩ = (2/3 − 1/3) / (1 − 1/3) = 1/2.
    const whole = row('5H2', null)!;
    expect(whole.n).toBe(2);
    expect(whole.pre).toBeCloseTo(1 / 3, 12);
    expect(whole.post).toBeCloseTo(2 / 3, 12);
    expect(whole.gain).toBeCloseTo(1 / 2, 12);
    // Shadows: before (1/2 + 0) / 2 = 1/4, after (1/2 + 1) / 2 = 3/4, ⟨g⟩ = (3/4 − 1/4) / (3/4) = 2/3.
    expect(row('5H2', 'shadows')).toMatchObject({ n: 2 });
    expect(row('5H2', 'shadows')!.pre).toBeCloseTo(0.25, 12);
    expect(row('5H2', 'shadows')!.post).toBeCloseTo(0.75, 12);
    expect(row('5H2', 'shadows')!.gain).toBeCloseTo(2 / 3, 12);
    // Refraction: before (0 + 1) / 2, after (1 + 0) / 2: no gain.
    expect(row('5H2', 'refraction')).toEqual({ concept: 'refraction', n: 2, pre: 0.5, post: 0.5, gain: 0 });
  });

  it('gives no gain where the class average before was 100 %, and the drop after where it was not', () => {
    // L4's early file had only the test before: the test after comes from the later CSV.
    expect(row('5H3', null)).toMatchObject({ n: 1, pre: 1, gain: null });
    expect(row('5H3', null)!.post).toBeCloseTo(2 / 3, 12);
    expect(row('5H3', 'shadows')).toEqual({ concept: 'shadows', n: 1, pre: 1, post: 0.5, gain: null });
    expect(row('5H3', 'refraction')).toEqual({ concept: 'refraction', n: 1, pre: 1, post: 1, gain: null });
  });

  it("is the gain of the class averages, not the average of the learners' gains", () => {
    // 5H2's learners' own gains on the whole test: L1 (2/3 − 1/3) / (2/3) = 1/2, L2 (2/3 − 1/3) / (2/3) = 1/2: equal here, so take shadows:
    // L1 (1/2 − 1/2) / (1/2) = 0, L2 (1 − 0) / 1 = 1: their mean 1/2 differs from ⟨g⟩ = 2/3.
    expect(normalizedGain(0.25, 0.75)).toBeCloseTo(2 / 3, 12);
    expect(row('5H2', 'shadows')!.gain).not.toBeCloseTo(0.5, 3);
  });
});
