import { msg, str } from '@lit/localize';
import type { CodeLab } from '../../../quest/code-labs/code-goal.ts';
import type { CaseFailure, LabAnswer, Tolerance, Vec3 } from '../../../quest/code-labs/code-lab-grading.ts';
import { numberList } from '../../../i18n/number-format.ts';
import { LAB_WORDING } from './lab-failure-wording.ts';
import { labNumber, labValue } from './lab-numbers.ts';

/** A kind of case as the result list names it: the misconception its edge case tests. */
export function caseKindName(kind: string): string {
  switch (kind) {
    case 'hit-from-outside':
      return msg('a ray from outside that hits');
    case 'miss':
      return msg('a ray that misses');
    case 'sphere-behind':
      return msg('a sphere behind the ray’s origin');
    case 'inside-sphere':
      return msg('a ray that starts inside the sphere');
    case 'tangent':
      return msg('a ray that just touches the sphere');
    case 'off-centre':
      return msg('a sphere whose centre is not at (0, 0, 0)');
    case 'mirror-slanted':
      return msg('a ray at 45° onto a floor');
    case 'mirror-head-on':
      return msg('a ray straight onto the mirror');
    case 'mirror-grazing':
      return msg('a ray that grazes the mirror');
    case 'mirror-tilted':
      return msg('a mirror tilted along no axis');
    case 'into-glass-slanted':
      return msg('a ray at 45° from air into glass');
    case 'into-glass-straight':
      return msg('a ray straight into the glass');
    case 'out-of-glass-slanted':
      return msg('a ray from inside the glass out into the air');
    case 'total-internal-reflection':
      return msg('a ray inside the glass beyond the critical angle');
    case 'into-diamond':
      return msg('a ray into diamond, through a surface tilted along no axis');
    case 'phong-light-behind':
      return msg('a light behind the surface');
    case 'phong-in-the-highlight':
      return msg('an eye right in the highlight');
    case 'phong-beside-the-highlight':
      return msg('an eye beside the highlight');
    case 'phong-coloured-light':
      return msg('a coloured light on a tilted surface');
    case 'random':
      return msg('random cases');
    default:
      return boxCaseKindName(kind) ?? shadowCaseKindName(kind) ?? normalKindName(kind) ?? kind;
  }
}

/** The slab test lab's kinds of case (ray-box-edges.ts). */
function boxCaseKindName(kind: string): string | null {
  switch (kind) {
    case 'box-hit-from-outside':
      return msg('a ray from outside that hits the box');
    case 'box-miss':
      return msg('a ray that misses the box');
    case 'box-behind':
      return msg('a box behind the ray’s origin');
    case 'inside-box':
      return msg('a ray that starts inside the box');
    case 'negative-direction':
      return msg('a ray going toward −x, −y and −z');
    case 'parallel-inside-slab':
      return msg('a ray parallel to a slab, inside it');
    case 'parallel-outside-slab':
      return msg('a ray parallel to a slab, outside it');
    case 'in-face-plane':
      return msg('a ray that runs exactly in the plane of a face');
    case 'touches-edge':
      return msg('a ray that just touches an edge of the box');
    case 'random-box':
      return msg('random rays and boxes');
    default:
      return null;
  }
}

/** The shadow-test lab's kinds of case (shadow-edges.ts). */
function shadowCaseKindName(kind: string): string | null {
  switch (kind) {
    case 'blocked':
      return msg('a sphere between the point and the light');
    case 'nothing-in-the-way':
      return msg('nothing between the point and the light');
    case 'beyond-the-light':
      return msg('a sphere beyond the light');
    case 'behind-the-point':
      return msg('a sphere behind the point');
    case 'own-sphere':
      return msg('a point on a sphere, lit by a light it faces');
    case 'several-spheres':
      return msg('several spheres, only the last one in the way');
    case 'random-shadow':
      return msg('random points, lights and spheres');
    default:
      return null;
  }
}

/** The cosine-bounce lab's normals (cosine-bounce-normals.ts). */
function normalKindName(kind: string): string | null {
  switch (kind) {
    case 'normal-plus-z':
      return msg('the normal (0, 0, 1)');
    case 'normal-minus-z':
      return msg('the normal (0, 0, −1)');
    case 'normal-plus-y':
      return msg('the normal (0, 1, 0), a floor’s');
    case 'normal-slanted':
      return msg('a normal along no axis');
    default:
      return null;
  }
}

/** A value of a case's input spelled out: numbers to 6 digits, vectors and colours as (x, y, z), objects and lists by their parts. */
function valueText(value: unknown): string {
  if (typeof value === 'number') return labNumber(value);
  if (Array.isArray(value)) return `[${numberList(value.map(valueText))}]`;
  if (typeof value !== 'object' || value === null) return String(value);
  const parts = value as Record<string, unknown>;
  if (['x', 'y', 'z'].every((key) => typeof parts[key] === 'number')) return labValue(value);
  if (['r', 'g', 'b'].every((key) => typeof parts[key] === 'number')) return labValue(value);
  return `{ ${Object.entries(parts)
    .map(([key, part]) => `${key}: ${valueText(part)}`)
    .join(', ')} }`;
}

/** The case's input, spelled out by the names the signature gives the arguments: "origin (0, 0, -5), direction (0, 0, 1), …". */
export function caseInput(signature: string, args: unknown[]): string {
  const names =
    /\(([^)]*)\)/
      .exec(signature)?.[1]
      ?.split(',')
      .map((name) => name.trim()) ?? [];
  return args.map((arg, index) => `${names[index] ?? `#${index + 1}`} ${valueText(arg)}`).join(', ');
}

/** An answer in words: null as what "none" means in this lab, a number as the distance t, anything else spelled out. */
function answerText(lab: CodeLab, answer: LabAnswer): string {
  if (answer === null) return LAB_WORDING[lab]?.none?.() ?? msg('null (no hit)');
  return typeof answer === 'number' ? `t = ${labNumber(answer)}` : labValue(answer);
}

/** What a lab's function must return, said when it returned something else. */
function answerKindText(tolerance: Tolerance): string {
  switch (tolerance.answer) {
    case 'number':
      return msg('return a number or null');
    case 'vector':
    case 'direction':
      return msg('return a vector such as vec(x, y, z)');
    case 'colour':
      return msg('return a colour such as { r: 0.5, g: 0.2, b: 0.1 }');
    case 'boolean':
      return msg('return true or false');
  }
}

/** What was expected and what came back, in words: the lab's own wording where it has one (lab-failure-wording.ts), else the general one. */
export function failureText(failure: CaseFailure, lab: CodeLab, tolerance: Tolerance): string {
  const expectedText = answerText(lab, failure.labCase.expected);
  const gotText = failure.gotValue === null ? labValue(failure.got) : answerText(lab, failure.gotValue);
  const wording = LAB_WORDING[lab];
  switch (failure.reason) {
    case 'threw': {
      const message = failure.message ?? '';
      return failure.line ? msg(str`Your function threw ${message} at line ${failure.line}.`) : msg(str`Your function threw ${message}.`);
    }
    case 'wrong-type':
      return msg(str`Expected ${expectedText}, got ${labValue(failure.got)}: ${answerKindText(tolerance)}.`);
    case 'not-a-number':
      return (
        wording?.notANumber?.(expectedText, failure) ??
        msg(str`Expected ${expectedText}, got ${labValue(failure.got)}: is something under a square root negative, or divided by 0?`)
      );
    case 'not-unit': {
      const value = failure.gotValue as Vec3;
      const size = labNumber(Math.hypot(value.x, value.y, value.z));
      return msg(str`Expected ${expectedText}, got ${gotText}: the right way, but of length ${size} instead of 1.`);
    }
    case 'expected-hit':
      return wording?.expectedHit?.(expectedText) ?? msg(str`Expected ${expectedText}, got ${gotText}.`);
    case 'expected-miss':
      return wording?.expectedMiss?.(expectedText, gotText, failure) ?? msg(str`Expected ${expectedText}, got ${gotText}.`);
    case 'wrong-value':
      return (
        wording?.wrongValue?.(expectedText, gotText, failure) ??
        (typeof failure.gotValue === 'number'
          ? msg(str`Expected ${expectedText}, got t = ${labValue(failure.got)}.`)
          : msg(str`Expected ${expectedText}, got ${gotText}.`))
      );
  }
}

/** The lab's vector library, as the panel documents it (public/code-lab-sandbox.html defines it). */
export function vectorLibrary(): [call: string, meaning: string][] {
  return [
    ['vec(x, y, z)', msg('a vector: an object with x, y and z')],
    ['add(a, b), sub(a, b)', msg('a + b, a − b')],
    ['scale(a, s)', msg('a times the number s')],
    ['dot(a, b)', msg('the dot product a · b')],
    ['cross(a, b)', msg('the cross product a × b')],
    ['length(a)', msg('the length |a|')],
    ['normalize(a)', msg('a with length 1')],
    ['mix(a, b, t)', msg('a + (b − a) · t')],
  ];
}

/** The sandbox page did not load: nothing of the learner's code ran, so nothing about it is said. */
export function sandboxUnavailableText(): string {
  return msg(
    'Your code was not run: the code lab’s safe room (a separate page that runs your code) did not load. Without a network it loads only if this browser keeps a copy of the app: the Menu says whether it does. Reload the page to try again.',
  );
}

/**
 * The first line of a failed report: how many runs passed their own checks, or, when every one
 * did, that only the χ² test over all of them failed (so "12 of 12 runs pass" does not stand in
 * the failure's colour unexplained).
 */
export function failedRunsLine({ passedRuns, runs }: { passedRuns: number; runs: number }): string {
  return passedRuns === runs ? msg(str`All ${runs} runs pass one by one; together they fail a χ² test.`) : msg(str`${passedRuns} of ${runs} runs pass.`);
}
