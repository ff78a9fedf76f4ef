import { describe, expect, it } from 'vitest';
import { PHONG_EDGES } from '../../../../src/quest/code-labs/phong-edges.ts';
import { PHONG_TOLERANCE, phongCases } from '../../../../src/quest/code-labs/phong-lab.ts';
import { RAY_BOX_TOLERANCE, rayBoxCases } from '../../../../src/quest/code-labs/ray-box-lab.ts';
import { RAY_SPHERE_TOLERANCE, raySphereCases } from '../../../../src/quest/code-labs/ray-sphere-lab.ts';
import { REFRACTION_TOLERANCE, refractionCases } from '../../../../src/quest/code-labs/refraction-lab.ts';
import { SHADOW_TOLERANCE, shadowCases } from '../../../../src/quest/code-labs/shadow-lab.ts';
import { failureText } from '../../../../src/ui/game/code-lab/code-lab-texts.ts';
import { gradeFunction } from '../../../support/code-lab-grade.ts';

/** The panel's words for the first case `learner` fails. */
function wordsFor(
  ...[cases, tolerance, learner, lab]: [
    Parameters<typeof gradeFunction>[0],
    Parameters<typeof gradeFunction>[1],
    (...args: never[]) => unknown,
    Parameters<typeof failureText>[1],
  ]
) {
  const failure = gradeFunction(cases, tolerance, learner).firstFailure;
  if (!failure) throw new Error('expected a failure');
  return failureText(failure, lab, tolerance);
}

describe('each lab’s own words for a failing case', () => {
  it('ray–sphere: a miss answered, and a hit behind the origin', () => {
    const cases = raySphereCases(['hit-from-outside', 'sphere-behind'], 0, 1);
    expect(wordsFor(cases, RAY_SPHERE_TOLERANCE, () => null, 'ray-sphere')).toBe('Expected t = 4, got null: the ray does hit the sphere.');
    expect(wordsFor(cases.slice(1), RAY_SPHERE_TOLERANCE, () => -4, 'ray-sphere')).toMatch(/: only a hit in front of the ray’s origin \(t > 0\) counts\.$/);
  });

  it('refraction: null is total internal reflection', () => {
    const cases = refractionCases(['into-glass-straight'], 0, 1);
    expect(wordsFor(cases, REFRACTION_TOLERANCE, () => null, 'refraction')).toMatch(/, got null: here the ray is not totally reflected, it goes through\.$/);
  });

  it('ray–box: NaN from 0 · Infinity, and a hit where the ray misses', () => {
    const cases = rayBoxCases(['box-miss'], 0, 1);
    expect(wordsFor(cases, RAY_BOX_TOLERANCE, () => NaN, 'ray-box')).toMatch(/: 0 · Infinity is NaN in JavaScript, and every comparison with NaN is false\.$/);
    expect(wordsFor(cases, RAY_BOX_TOLERANCE, () => 2, 'ray-box')).toBe(
      'Expected null (no hit), got t = 2: the ray is never inside all three slabs at once in front of its origin.',
    );
  });

  it('shadow: says what may block the light', () => {
    const cases = shadowCases(['behind-the-point'], 0, 1);
    expect(wordsFor(cases, SHADOW_TOLERANCE, () => true, 'shadow')).toMatch(/^Expected false, got true: only a sphere hit at a t between 0/);
  });

  it('Phong: a light behind the surface is named as such, another wrong colour is only spelled out', () => {
    const [behind, inTheHighlight] = phongCases(PHONG_EDGES, 0, 1);
    const grey = () => ({ r: 0.5, g: 0.5, b: 0.5 });
    expect(wordsFor([behind!], PHONG_TOLERANCE, grey, 'phong')).toBe(
      'Expected (0, 0, 0), got (0.5, 0.5, 0.5): the light is behind the surface here, L points below it (N·L < 0), so it adds nothing, no diffuse light and no highlight.',
    );
    expect(wordsFor([inTheHighlight!], PHONG_TOLERANCE, grey, 'phong')).toMatch(/^Expected \(.*\), got \(0\.5, 0\.5, 0\.5\)\.$/);
  });
});
