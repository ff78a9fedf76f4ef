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

/** A colour as the learner's code returns it: linear red, green and blue, each 0 or more (not clamped). */
export interface Rgb {
  r: number;
  g: number;
  b: number;
}

/** An answer a lab's function may give: a number, a vector, a colour, true or false, or null for "none" (no hit, no refracted ray). */
export type LabAnswer = number | Vec3 | Rgb | boolean | null;

/** One case: its kind (`random` or a named edge case), the arguments in order, and the tracer's answer. */
export interface LabCase {
  kind: string;
  args: unknown[];
  expected: LabAnswer;
}

/** What the learner's function did on one case, as the sandbox reports it. */
export type LabOutcome = { returned: unknown } | { threw: string; line: number | null };

/**
 * Why a case failed: the answer's value or kind was wrong, or the function threw.
 * `expected-miss`: the tracer's answer is null (no hit, no refracted ray) and the learner's
 * is not; `expected-hit`: the other way round. `not-unit`: a direction of the wrong length.
 */
export type FailureReason = 'wrong-value' | 'expected-miss' | 'expected-hit' | 'not-a-number' | 'not-unit' | 'wrong-type' | 'threw';

export interface CaseFailure {
  index: number;
  labCase: LabCase;
  reason: FailureReason;
  /** What came back, as the function returned it (the panel spells it out in the learner's language); undefined when it threw. */
  got: unknown;
  /** The learner's answer, when it was of the kind asked for (to draw where their function said the ray goes). */
  gotValue: LabAnswer;
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

/**
 * What kind of answer a lab asks for, and how close to the tracer's it must be. Numbers,
 * vectors and colours may be null where the tracer's answer is ("none").
 * - `number`: within `relative` of its size, but never less than `relative` itself;
 * - `vector`: each component so, within `relative` of the vector's length (at least 1);
 * - `direction`: at most `radians` from the tracer's direction, and of length 1 within `length`;
 * - `colour`: each channel within `relative` of the brightest (at least 1);
 * - `boolean`: the same truth value.
 */
export type Tolerance =
  | { answer: 'number'; relative: number }
  | { answer: 'vector'; relative: number }
  | { answer: 'direction'; radians: number; length: number }
  | { answer: 'colour'; relative: number }
  | { answer: 'boolean' };

const finite = (value: unknown): value is number => typeof value === 'number' && Number.isFinite(value);
const isVector = (value: unknown): value is Vec3 =>
  typeof value === 'object' && value !== null && ['x', 'y', 'z'].every((key) => typeof (value as Record<string, unknown>)[key] === 'number');
const isColour = (value: unknown): value is Rgb =>
  typeof value === 'object' && value !== null && ['r', 'g', 'b'].every((key) => typeof (value as Record<string, unknown>)[key] === 'number');

const length = (v: Vec3) => Math.hypot(v.x, v.y, v.z);

/** The angle between two directions, in radians (atan2 of |a×b| and a·b: exact near 0, where acos is not). */
function angleBetween(a: Vec3, b: Vec3): number {
  const cross = Math.hypot(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
  return Math.atan2(cross, a.x * b.x + a.y * b.y + a.z * b.z);
}

/** Whether each pair of numbers is within `relative` of the larger of 1 and `size`. */
const closeAll = (got: number[], expected: number[], relative: number, size: number) =>
  got.every((value, i) => Math.abs(value - expected[i]!) <= relative * Math.max(1, size));

/**
 * Whether one answer is right: of the kind the lab asks for (or null exactly where the
 * tracer's answer is null), finite, and within the lab's tolerance of the tracer's answer.
 */
export function judge(labCase: LabCase, outcome: LabOutcome, tolerance: Tolerance, index: number): CaseFailure | null {
  const fail = (reason: FailureReason, got: unknown, gotValue: LabAnswer = null, extra: Partial<CaseFailure> = {}): CaseFailure => ({
    index,
    labCase,
    reason,
    got,
    gotValue,
    ...extra,
  });
  if ('threw' in outcome) return fail('threw', undefined, null, { message: outcome.threw, line: outcome.line });
  const got = outcome.returned;
  const expected = labCase.expected;
  switch (tolerance.answer) {
    case 'boolean':
      if (typeof got !== 'boolean') return fail('wrong-type', got);
      return got === expected ? null : fail('wrong-value', got, got);
    case 'number': {
      if (got !== null && typeof got !== 'number') return fail('wrong-type', got);
      if (got !== null && !finite(got)) return fail('not-a-number', got);
      if (expected === null || got === null) return nullMismatch(expected, got, fail);
      const want = expected as number;
      return closeAll([got], [want], tolerance.relative, Math.abs(want)) ? null : fail('wrong-value', got, got);
    }
    case 'vector':
    case 'direction': {
      if (got !== null && !isVector(got)) return fail('wrong-type', got);
      if (got !== null && ![got.x, got.y, got.z].every(finite)) return fail('not-a-number', got);
      if (expected === null || got === null) return nullMismatch(expected, got, fail);
      const want = expected as Vec3;
      const answer = { x: got.x, y: got.y, z: got.z };
      if (tolerance.answer === 'vector') {
        const close = closeAll([got.x, got.y, got.z], [want.x, want.y, want.z], tolerance.relative, length(want));
        return close ? null : fail('wrong-value', got, answer);
      }
      // A zero vector has no direction (its angle to anything comes out 0): it is a wrong one, not a short one.
      if (length(got) === 0 || angleBetween(got, want) > tolerance.radians) return fail('wrong-value', got, answer);
      return Math.abs(length(got) - 1) <= tolerance.length ? null : fail('not-unit', got, answer);
    }
    case 'colour': {
      if (got !== null && !isColour(got)) return fail('wrong-type', got);
      if (got !== null && ![got.r, got.g, got.b].every(finite)) return fail('not-a-number', got);
      if (expected === null || got === null) return nullMismatch(expected, got, fail);
      const want = expected as Rgb;
      const close = closeAll([got.r, got.g, got.b], [want.r, want.g, want.b], tolerance.relative, Math.max(want.r, want.g, want.b));
      return close ? null : fail('wrong-value', got, { r: got.r, g: got.g, b: got.b });
    }
  }
}

/** Where the tracer's answer or the learner's is null: right only when both are. */
function nullMismatch(
  expected: LabAnswer,
  got: LabAnswer,
  fail: (reason: FailureReason, got: unknown, gotValue?: LabAnswer) => CaseFailure,
): CaseFailure | null {
  if (expected === null) return got === null ? null : fail('expected-miss', got, got);
  return fail('expected-hit', null);
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
