/**
 * Grading a code lab (spec/code-labs.md §2): the learner's function has been run on every
 * case (in the sandbox, code-lab-sandbox.html) and its answers come back here as plain data;
 * each is compared with the tracer's own answer for that case, within a tolerance the lab
 * states. Pure: the same cases and answers always give the same report.
 */

/** A point or direction as the learner's code sees it: a plain object, cloneable to the sandbox. */
export interface Vec3 {
  x: number;
  y: number;
  z: number;
}

/** One case: its kind (`random` or a named edge case), the arguments in order, and the tracer's answer. */
export interface LabCase {
  kind: string;
  args: unknown[];
  expected: number | null;
}

/** What the learner's function did on one case, as the sandbox reports it. */
export type LabOutcome = { returned: unknown } | { threw: string; line: number | null };

/** Why a case failed: the answer's value or kind was wrong, or the function threw. */
export type FailureReason = 'wrong-value' | 'expected-miss' | 'expected-hit' | 'not-a-number' | 'wrong-type' | 'threw';

export interface CaseFailure {
  index: number;
  labCase: LabCase;
  reason: FailureReason;
  /** What came back, as text a learner can read ("undefined", "NaN", "'5'", "4.2"). */
  got: string;
  /** The learner's number, when it was one (to draw where their function said the ray hits). */
  gotValue: number | null;
  /** For `threw`: the error's message and the learner's line, when known. */
  message?: string;
  line?: number | null;
}

export interface LabReport {
  total: number;
  passed: number;
  /** Per kind of case, how many passed of how many, in the order the kinds first appear. */
  kinds: { kind: string; passed: number; total: number }[];
  firstFailure: CaseFailure | null;
}

/** How close a number must be to the tracer's: `relative` of its size, but never less than `relative` itself. */
export interface Tolerance {
  relative: number;
}

/** How a value came back, spelled out for the learner. */
export function describeValue(value: unknown): string {
  if (typeof value === 'string') return JSON.stringify(value);
  if (typeof value === 'number') return Number.isNaN(value) ? 'NaN' : String(value);
  if (value === null || value === undefined || typeof value === 'boolean') return String(value);
  if (Array.isArray(value)) return 'array';
  return typeof value;
}

/** Whether one answer is right: null for "no hit", or a finite number within the tolerance of the tracer's. */
export function judge(labCase: LabCase, outcome: LabOutcome, tolerance: Tolerance, index: number): CaseFailure | null {
  const fail = (reason: FailureReason, got: string, gotValue: number | null = null, extra: Partial<CaseFailure> = {}): CaseFailure => ({
    index,
    labCase,
    reason,
    got,
    gotValue,
    ...extra,
  });
  if ('threw' in outcome) return fail('threw', '', null, { message: outcome.threw, line: outcome.line });
  const got = outcome.returned;
  if (got !== null && typeof got !== 'number') return fail('wrong-type', describeValue(got));
  if (typeof got === 'number' && !Number.isFinite(got)) return fail('not-a-number', describeValue(got));
  if (labCase.expected === null) return got === null ? null : fail('expected-miss', describeValue(got), got);
  if (got === null) return fail('expected-hit', 'null');
  const allowed = tolerance.relative * Math.max(1, Math.abs(labCase.expected));
  return Math.abs(got - labCase.expected) <= allowed ? null : fail('wrong-value', describeValue(got), got);
}

/** The report of a whole run: every case judged, the first failure kept to spell out and draw. */
export function gradeLab(cases: readonly LabCase[], outcomes: readonly LabOutcome[], tolerance: Tolerance): LabReport {
  const kinds = new Map<string, { kind: string; passed: number; total: number }>();
  let passed = 0;
  let firstFailure: CaseFailure | null = null;
  cases.forEach((labCase, index) => {
    const outcome = outcomes[index] ?? { threw: 'no answer', line: null };
    const failure = judge(labCase, outcome, tolerance, index);
    const tally = kinds.get(labCase.kind) ?? { kind: labCase.kind, passed: 0, total: 0 };
    kinds.set(labCase.kind, tally);
    tally.total++;
    if (failure) firstFailure ??= failure;
    else {
      tally.passed++;
      passed++;
    }
  });
  return { total: cases.length, passed, kinds: [...kinds.values()], firstFailure };
}
