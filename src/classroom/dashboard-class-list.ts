import type { ClassLearner } from './dashboard-learners.ts';

/**
 * The class list: the participant codes a teacher handed out, pasted one per line, checked
 * against the learners whose results were read, so that the dashboard can say who has
 * handed in, who is missing, and which results carry a code that is not on the list (a typo,
 * or a pupil of another class).
 *
 * Codes are compared trimmed and case-insensitively ("5h2-03" is "5H2-03"): pupils type
 * them, and a typed code differs from the slip in case far more often than in anything else.
 */

/** A code as it is compared. */
export function codeKey(code: string): string {
  return code.trim().toLocaleLowerCase('en');
}

/**
 * The codes of a pasted list: one per line (a column copied from a spreadsheet is one per
 * line too), empty lines left out, each code once, in the list's order.
 */
export function parseClassList(text: string): string[] {
  const codes = new Map<string, string>();
  for (const line of text.split(/\r\n|\r|\n/)) {
    const code = line.trim();
    if (code !== '' && !codes.has(codeKey(code))) codes.set(codeKey(code), code);
  }
  return [...codes.values()];
}

export interface ClassListCheck {
  /** The list's codes with the learners who handed in under them, in the list's order. */
  handedIn: { code: string; learners: ClassLearner[] }[];
  /** The list's codes nobody handed in under. */
  missing: string[];
  /** Learners whose code is not on the list (the code they typed, '' when none was asked), with their files. */
  notOnList: ClassLearner[];
}

export function checkClassList(codes: readonly string[], learners: readonly ClassLearner[]): ClassListCheck {
  const byCode = new Map<string, ClassLearner[]>();
  for (const learner of learners) {
    const key = codeKey(learner.participant);
    byCode.set(key, [...(byCode.get(key) ?? []), learner]);
  }
  const onList = new Set(codes.map(codeKey));
  const handedIn = codes.filter((code) => byCode.has(codeKey(code))).map((code) => ({ code, learners: byCode.get(codeKey(code))! }));
  return {
    handedIn,
    missing: codes.filter((code) => !byCode.has(codeKey(code))),
    notOnList: learners.filter((learner) => !onList.has(codeKey(learner.participant))),
  };
}
