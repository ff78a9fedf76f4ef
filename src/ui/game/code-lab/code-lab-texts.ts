import { msg, str } from '@lit/localize';
import type { CodeLab } from '../../../quest/code-labs/code-goal.ts';
import type { CaseFailure, Vec3 } from '../../../quest/code-labs/code-lab-grading.ts';

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
    case 'random':
      return msg('random rays and spheres');
    default:
      return boxCaseKindName(kind) ?? kind;
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

const numberText = (value: number) => String(Number(value.toPrecision(6)));
const vectorText = (v: Vec3) => `(${numberText(v.x)}, ${numberText(v.y)}, ${numberText(v.z)})`;

/** The case's input, spelled out: the arguments by the names the lab's function gives them. */
export function caseInput(lab: CodeLab, args: unknown[]): string {
  switch (lab) {
    case 'ray-sphere': {
      const [origin, direction, center, radius] = args as [Vec3, Vec3, Vec3, number];
      return `origin ${vectorText(origin)}, direction ${vectorText(direction)}, center ${vectorText(center)}, radius ${numberText(radius)}`;
    }
    case 'ray-box': {
      const [origin, direction, boxMin, boxMax] = args as [Vec3, Vec3, Vec3, Vec3];
      return `origin ${vectorText(origin)}, direction ${vectorText(direction)}, boxMin ${vectorText(boxMin)}, boxMax ${vectorText(boxMax)}`;
    }
    case 'pixel-samples':
      return `n = ${String(args[0])}`;
  }
}

/** What was expected and what came back, in words. */
export function failureText(failure: CaseFailure, lab: CodeLab): string {
  const expected = failure.labCase.expected;
  const expectedText = expected === null ? msg('null (no hit)') : `t = ${numberText(expected)}`;
  switch (failure.reason) {
    case 'threw': {
      const message = failure.message ?? '';
      return failure.line ? msg(str`Your function threw ${message} at line ${failure.line}.`) : msg(str`Your function threw ${message}.`);
    }
    case 'wrong-type':
      return msg(str`Expected ${expectedText}, got ${failure.got}: return a number or null.`);
    case 'not-a-number':
      return lab === 'ray-box'
        ? msg(str`Expected ${expectedText}, got ${failure.got}: 0 · Infinity is NaN in JavaScript, and every comparison with NaN is false.`)
        : msg(str`Expected ${expectedText}, got ${failure.got}: is something under a square root negative, or divided by 0?`);
    case 'expected-hit':
      return lab === 'ray-box'
        ? msg(str`Expected ${expectedText}, got null: the ray does hit the box.`)
        : msg(str`Expected ${expectedText}, got null: the ray does hit the sphere.`);
    case 'expected-miss':
      if (lab === 'ray-sphere') return msg(str`Expected ${expectedText}, got t = ${failure.got}: only a hit in front of the ray’s origin (t > 0) counts.`);
      return failure.labCase.kind === 'in-face-plane'
        ? msg(str`Expected ${expectedText}, got t = ${failure.got}: a ray exactly in the plane of a face counts as a miss here.`)
        : msg(str`Expected ${expectedText}, got t = ${failure.got}: the ray is never inside all three slabs at once in front of its origin.`);
    case 'wrong-value':
      return msg(str`Expected ${expectedText}, got t = ${failure.got}.`);
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
