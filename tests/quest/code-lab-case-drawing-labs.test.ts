import { describe, expect, it } from 'vitest';
import { caseDrawingExtent, type CaseDrawing } from '../../src/quest/code-labs/case-drawing.ts';
import { codeGoalSchema, type CodeGoal } from '../../src/quest/code-labs/code-goal.ts';
import type { CaseFailure, LabCase, Tolerance, Vec3 } from '../../src/quest/code-labs/code-lab-grading.ts';
import { drawFailingCase } from '../../src/quest/code-labs/lab-drawings.ts';
import { MIRROR_TOLERANCE, mirrorCases } from '../../src/quest/code-labs/mirror-lab.ts';
import { RAY_BOX_TOLERANCE, rayBoxCases } from '../../src/quest/code-labs/ray-box-lab.ts';
import { REFRACTION_TOLERANCE, refractionCases } from '../../src/quest/code-labs/refraction-lab.ts';
import { gradeFunction } from '../support/code-lab-grade.ts';

const goalOf = (lab: string, edges: readonly string[]): CodeGoal =>
  codeGoalSchema.parse({
    code: { lab, function: 'f', signature: 'f()', contract: { en: 'c', nl: 'c' }, skeleton: 'function f() {}', cases: { edges, random: 10, seed: 3 } },
  });

/** The drawing of the first case a learner's function fails. */
function drawFirstFailure(
  goal: CodeGoal,
  cases: LabCase[],
  tolerance: Tolerance,
  learner: (...args: never[]) => unknown,
): { failure: CaseFailure; drawing: CaseDrawing } {
  const failure = gradeFunction(cases, tolerance, learner).firstFailure;
  if (!failure) throw new Error('expected a failure');
  const drawing = drawFailingCase(goal, failure);
  if (!drawing) throw new Error(`${goal.code.lab} draws its cases`);
  return { failure, drawing };
}

const plus = (a: Vec3, b: Vec3, s = 1): Vec3 => ({ x: a.x + s * b.x, y: a.y + s * b.y, z: a.z + s * b.z });
const dot = (a: Vec3, b: Vec3) => a.x * b.x + a.y * b.y + a.z * b.z;
const ORIGIN = { x: 0, y: 0, z: 0 };
const tipOf = (drawing: CaseDrawing, mark: string) => drawing.segments.find((segment) => segment.mark === mark)?.to;

describe('a failing mirror case drawn in 3D', () => {
  const edges = ['mirror-slanted', 'mirror-head-on'] as const;
  const goal = goalOf('mirror', edges);

  it('draws d arriving at the hit, the normal, and the tracer’s and the learner’s reflection from it', () => {
    // Not reflected at all: the ray goes on into the mirror.
    const { failure, drawing } = drawFirstFailure(goal, mirrorCases(edges, 10, 3), MIRROR_TOLERANCE, (d: Vec3) => d);
    expect(failure.labCase.kind).toBe('mirror-slanted');
    const [d, n] = failure.labCase.args as [Vec3, Vec3];
    expect(drawing.segments.map((segment) => segment.mark)).toEqual(['ray', 'normal', 'expected', 'got']);
    expect(drawing.segments[0]).toEqual({ from: plus(ORIGIN, d, -1), to: ORIGIN, mark: 'ray', arrow: true });
    expect(drawing.segments[1]).toEqual({ from: ORIGIN, to: n, mark: 'normal' });
    // 45° onto the floor: the tracer's goes up again, the learner's on down.
    expect(tipOf(drawing, 'expected')?.y).toBeCloseTo(Math.SQRT1_2);
    expect(tipOf(drawing, 'got')).toEqual(d);
    expect(drawing.points).toEqual([
      { at: tipOf(drawing, 'expected'), mark: 'expected' },
      { at: tipOf(drawing, 'got'), mark: 'got' },
    ]);
  });

  it('draws a learner’s vector of the wrong length as long as it is, up to twice a unit', () => {
    const twice = drawFirstFailure(goal, mirrorCases(edges, 10, 3), MIRROR_TOLERANCE, (d: Vec3, n: Vec3) =>
      plus(plus(d, n, -2 * dot(d, n)), plus(d, n, -2 * dot(d, n))),
    );
    expect(twice.failure.reason).toBe('not-unit');
    const got = tipOf(twice.drawing, 'got') as Vec3;
    expect(Math.hypot(got.x, got.y, got.z)).toBeCloseTo(2);
    const huge = drawFirstFailure(goal, mirrorCases(edges, 10, 3), MIRROR_TOLERANCE, (d: Vec3, n: Vec3) => plus(ORIGIN, plus(d, n, -2 * dot(d, n)), 1000));
    const far = tipOf(huge.drawing, 'got') as Vec3;
    expect(Math.hypot(far.x, far.y, far.z)).toBeCloseTo(2);
  });
});

describe('a failing refraction case drawn in 3D', () => {
  it('draws the normal through the hit on both sides and the two refracted directions', () => {
    const edges = ['into-glass-slanted'] as const;
    // Not bent at all: the ray goes straight on.
    const { failure, drawing } = drawFirstFailure(goalOf('refraction', edges), refractionCases(edges, 0, 3), REFRACTION_TOLERANCE, (d: Vec3) => d);
    const [d, n] = failure.labCase.args as [Vec3, Vec3];
    expect(drawing.segments[1]).toEqual({ from: { x: -n.x, y: -n.y, z: -n.z }, to: n, mark: 'normal' });
    expect(tipOf(drawing, 'got')).toEqual(d);
    // Bent toward the normal: sin 28.1° = sin 45° / 1.5.
    expect(tipOf(drawing, 'expected')?.x).toBeCloseTo(Math.SQRT1_2 / 1.5);
  });

  it('on total internal reflection draws no expected direction, only the learner’s', () => {
    const edges = ['total-internal-reflection'] as const;
    const { failure, drawing } = drawFirstFailure(goalOf('refraction', edges), refractionCases(edges, 0, 3), REFRACTION_TOLERANCE, (d: Vec3) => d);
    expect(failure.reason).toBe('expected-miss');
    expect(drawing.segments.map((segment) => segment.mark)).toEqual(['ray', 'normal', 'got']);
    expect(drawing.points.map((point) => point.mark)).toEqual(['got']);
  });
});

describe('a failing ray–box case drawn in 3D', () => {
  it('draws the box, the ray past it and the expected and got hits on the ray', () => {
    const edges = ['box-hit-from-outside'] as const;
    // Where the ray leaves the box instead of where it enters: t_far for t_near.
    const cases = rayBoxCases(edges, 0, 3);
    const exit = (cases[0]!.expected as number) + 1;
    const { failure, drawing } = drawFirstFailure(goalOf('ray-box', edges), cases, RAY_BOX_TOLERANCE, () => exit);
    const [origin, direction, min, max] = failure.labCase.args as [Vec3, Vec3, Vec3, Vec3];
    const expected = failure.labCase.expected as number;
    expect(drawing.shapes).toEqual([{ kind: 'box', min, max }]);
    expect(drawing.points).toEqual([
      { at: plus(origin, direction, expected), mark: 'expected' },
      { at: plus(origin, direction, exit), mark: 'got' },
    ]);
    // The ray from (−3, −2, −6) reaches past the box's far corner (1, 1, 1).
    expect(drawing.segments[0]?.from).toEqual(origin);
    expect(drawing.segments[0]?.to.z).toBeGreaterThan(1);
    expect(caseDrawingExtent(drawing)).toContainEqual(max);
  });
});
