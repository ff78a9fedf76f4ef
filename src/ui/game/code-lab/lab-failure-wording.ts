import { msg, str } from '@lit/localize';
import type { CodeLab } from '../../../quest/code-labs/code-goal.ts';
import type { CaseFailure } from '../../../quest/code-labs/code-lab-grading.ts';
import { lightBehindSurface } from '../../../quest/code-labs/phong-lab.ts';
import { labValue } from './lab-numbers.ts';

/**
 * What one lab says about its own failures, where the general wording (code-lab-texts.ts)
 * would not name the misconception: what its "none" means, and why a case expected a hit, a
 * miss or another value. Each text receives the expected and the learner's answers in words.
 */
export interface LabWording {
  /** What null means in this lab ("no hit" unless said). */
  none?: () => string;
  notANumber?: (expectedText: string, failure: CaseFailure) => string;
  expectedHit?: (expectedText: string) => string;
  expectedMiss?: (expectedText: string, gotText: string, failure: CaseFailure) => string;
  /** Null: the general "Expected …, got …" says it all for this case. */
  wrongValue?: (expectedText: string, gotText: string, failure: CaseFailure) => string | null;
}

/** Why a shadow test's true or false is wrong: what may block the light, and what may not. */
function shadowWrongText(inShadow: boolean): string {
  return inShadow
    ? msg('Expected true, got false: a sphere is in the way between the point and the light.')
    : msg(
        'Expected false, got true: only a sphere hit at a t between 0 and the distance to the light blocks it; one behind the point or beyond the light does not.',
      );
}

/** Each lab's own wording; a lab not listed, or a failure its wording does not name, gets the general one. */
export const LAB_WORDING: Partial<Record<CodeLab, LabWording>> = {
  'ray-sphere': {
    expectedHit: (expectedText) => msg(str`Expected ${expectedText}, got null: the ray does hit the sphere.`),
    expectedMiss: (expectedText, _gotText, failure) =>
      msg(str`Expected ${expectedText}, got t = ${labValue(failure.got)}: only a hit in front of the ray’s origin (t > 0) counts.`),
  },
  refraction: {
    none: () => msg('null (total internal reflection)'),
    expectedHit: (expectedText) => msg(str`Expected ${expectedText}, got null: here the ray is not totally reflected, it goes through.`),
    expectedMiss: (expectedText, gotText) => msg(str`Expected ${expectedText}, got ${gotText}: here the ray cannot leave the glass.`),
  },
  'ray-box': {
    notANumber: (expectedText, failure) =>
      msg(str`Expected ${expectedText}, got ${labValue(failure.got)}: 0 · Infinity is NaN in JavaScript, and every comparison with NaN is false.`),
    expectedHit: (expectedText) => msg(str`Expected ${expectedText}, got null: the ray does hit the box.`),
    expectedMiss: (expectedText, _gotText, failure) =>
      failure.labCase.kind === 'in-face-plane'
        ? msg(str`Expected ${expectedText}, got t = ${labValue(failure.got)}: a ray exactly in the plane of a face counts as a miss here.`)
        : msg(str`Expected ${expectedText}, got t = ${labValue(failure.got)}: the ray is never inside all three slabs at once in front of its origin.`),
  },
  shadow: {
    wrongValue: (_expectedText, _gotText, failure) => shadowWrongText(failure.labCase.expected === true),
  },
  phong: {
    wrongValue: (expectedText, gotText, failure) =>
      lightBehindSurface(failure.labCase)
        ? msg(
            str`Expected ${expectedText}, got ${gotText}: the light is behind the surface here, L points below it (N·L < 0), so it adds nothing, no diffuse light and no highlight.`,
          )
        : null,
  },
};
