import { describe, expect, it } from 'vitest';
import { caseDrawingExtent } from '../../src/quest/code-labs/case-drawing.ts';
import { codeGoalSchema } from '../../src/quest/code-labs/code-goal.ts';
import { gradeLab, type LabAnswer, type LabCase, type Vec3 } from '../../src/quest/code-labs/code-lab-grading.ts';
import { drawFailingCase } from '../../src/quest/code-labs/lab-drawings.ts';
import { RAY_SPHERE_TOLERANCE, raySphereCases } from '../../src/quest/code-labs/ray-sphere-lab.ts';

const goal = codeGoalSchema.parse({
  code: {
    lab: 'ray-sphere',
    function: 'hitSphere',
    signature: 'hitSphere(origin, direction, center, radius)',
    contract: { en: 'c', nl: 'c' },
    skeleton: 'function hitSphere() {}',
    cases: { edges: ['sphere-behind', 'hit-from-outside'], random: 20, seed: 5 },
  },
});

/** The first failing case of a run where every case returns `answer(case)`. */
function firstFailure(answer: (labCase: LabCase) => LabAnswer) {
  const cases = raySphereCases(['sphere-behind', 'hit-from-outside'], 20, 5);
  const report = gradeLab(
    cases,
    cases.map((labCase) => ({ returned: answer(labCase) })),
    RAY_SPHERE_TOLERANCE,
  );
  if (!report.firstFailure) throw new Error('expected a failure');
  return report.firstFailure;
}

const on = (origin: Vec3, direction: Vec3, t: number) => ({ x: origin.x + t * direction.x, y: origin.y + t * direction.y, z: origin.z + t * direction.z });

describe('a failing ray–sphere case drawn in 3D', () => {
  it('puts the learner’s negative t behind the ray’s origin, with the sphere and no expected hit', () => {
    // "t < 0 accepted": the sphere behind the origin is answered with its near root, t = −6.
    const failure = firstFailure(() => -6);
    expect(failure.labCase.kind).toBe('sphere-behind');
    const drawing = drawFailingCase(goal, failure);
    if (!drawing) throw new Error('ray-sphere draws its cases');
    const [origin, direction, center, radius] = failure.labCase.args as [Vec3, Vec3, Vec3, number];
    expect(drawing.shapes).toEqual([{ kind: 'sphere', center, radius }]);
    expect(drawing.points).toEqual([{ at: on(origin, direction, -6), mark: 'got' }]);
    expect(drawing.segments.map((segment) => segment.mark)).toEqual(['ray', 'got']);
    expect(drawing.segments[0]?.from).toEqual(origin);
  });

  it('draws the expected and the got hit apart on the ray, and the ray reaches past both and the sphere', () => {
    const failure = firstFailure((labCase) => (labCase.kind === 'sphere-behind' ? null : typeof labCase.expected === 'number' ? labCase.expected + 1 : null));
    expect(failure.labCase.kind).toBe('hit-from-outside');
    const drawing = drawFailingCase(goal, failure);
    if (!drawing) throw new Error('ray-sphere draws its cases');
    const [origin, direction] = failure.labCase.args as [Vec3, Vec3];
    const expected = failure.labCase.expected as number;
    expect(drawing.points).toEqual([
      { at: on(origin, direction, expected), mark: 'expected' },
      { at: on(origin, direction, expected + 1), mark: 'got' },
    ]);
    const end = drawing.segments[0]?.to as Vec3;
    // Origin (0, 0, −5) towards +z past the sphere's far side at z = 1.
    expect(end.z).toBeGreaterThan(1);
    // The extent the view frames holds the origin, the end, both points and the sphere's box.
    const extent = caseDrawingExtent(drawing);
    expect(extent).toContainEqual(origin);
    expect(extent).toContainEqual({ x: 1, y: 1, z: 1 });
    expect(extent).toContainEqual(on(origin, direction, expected + 1));
  });

  it('draws the expected hit alone when the learner said no hit', () => {
    const failure = firstFailure((labCase) => (labCase.kind === 'sphere-behind' ? null : labCase.kind === 'hit-from-outside' ? null : labCase.expected));
    const drawing = drawFailingCase(goal, failure);
    expect(drawing?.points.map((point) => point.mark)).toEqual(['expected']);
  });
});
