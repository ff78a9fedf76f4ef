import { describe, expect, it } from 'vitest';
import type { CaseDrawing, CaseSegment } from '../../src/quest/code-labs/case-drawing.ts';
import { codeGoalSchema } from '../../src/quest/code-labs/code-goal.ts';
import type { Rgb, Vec3 } from '../../src/quest/code-labs/code-lab-grading.ts';
import { gradeSamples, type Point } from '../../src/quest/code-labs/code-lab-statistics.ts';
import { drawFailingCase } from '../../src/quest/code-labs/lab-drawings.ts';
import { PHONG_EDGES } from '../../src/quest/code-labs/phong-edges.ts';
import { lightBehindSurface, PHONG_TOLERANCE, phongCases, type PhongLight, type PhongMaterial } from '../../src/quest/code-labs/phong-lab.ts';
import { drawSampleRun, PIXEL_SAMPLES_SIGNIFICANCE, pixelSampleRuns } from '../../src/quest/code-labs/pixel-samples-lab.ts';
import { gradeFunction } from '../support/code-lab-grade.ts';
import { runCases } from '../support/code-lab-run.ts';

const dot = (a: Vec3, b: Vec3) => a.x * b.x + a.y * b.y + a.z * b.z;
const minus = (a: Vec3, b: Vec3): Vec3 => ({ x: a.x - b.x, y: a.y - b.y, z: a.z - b.z });
const unit = (a: Vec3): Vec3 => {
  const l = Math.hypot(a.x, a.y, a.z);
  return { x: a.x / l, y: a.y / l, z: a.z / l };
};
/** The direction of a segment, of length 1. */
const directionOf = (segment: CaseSegment | undefined): Vec3 => (segment ? unit(minus(segment.to, segment.from)) : { x: NaN, y: NaN, z: NaN });
const segmentOf = (drawing: CaseDrawing, label: string) => drawing.segments.find((segment) => segment.label === label);

describe('a failing Phong case drawn in 3D', () => {
  const goal = codeGoalSchema.parse({
    code: {
      lab: 'phong',
      function: 'shade',
      signature: 'shade()',
      contract: 'c',
      skeleton: 'function shade() {}',
      cases: { edges: PHONG_EDGES, random: 10, seed: 3 },
    },
  });
  // cos θ not clamped: a light behind the surface gives a negative colour.
  const unclamped = (point: Vec3, normal: Vec3, toEye: Vec3, light: PhongLight, material: PhongMaterial): Rgb => {
    const l = unit(minus(light.position, point));
    const nDotL = dot(normal, l);
    const r = minus({ x: 2 * nDotL * normal.x, y: 2 * nDotL * normal.y, z: 2 * nDotL * normal.z }, l);
    const highlight = material.specular * Math.pow(Math.max(dot(r, toEye), 0), material.shininess);
    const channel = (lc: number, c: number) => light.intensity * lc * (material.diffuse * nDotL * c + highlight);
    return { r: channel(light.color.r, material.color.r), g: channel(light.color.g, material.color.g), b: channel(light.color.b, material.color.b) };
  };
  const failure = gradeFunction(phongCases(PHONG_EDGES, 10, 3), PHONG_TOLERANCE, unclamped).firstFailure;

  it('draws N, L, V and R from the shading point, L pointing below the surface when the light is behind it', () => {
    expect(failure?.labCase.kind).toBe('phong-light-behind');
    if (!failure) return;
    expect(lightBehindSurface(failure.labCase)).toBe(true);
    const drawing = drawFailingCase(goal, failure);
    if (!drawing) throw new Error('the Phong lab draws its cases');
    // The case: the point at the origin, N up, V = (1, 1, 0)/√2, the light at (−1, −2, 0).
    expect(drawing.segments.map((segment) => [segment.label, segment.mark])).toEqual([
      ['N', 'normal'],
      ['L', 'light'],
      ['V', 'eye'],
      ['R', 'mirror'],
    ]);
    const n = directionOf(segmentOf(drawing, 'N'));
    const l = directionOf(segmentOf(drawing, 'L'));
    expect(n.y).toBeCloseTo(1);
    expect([l.x, l.y, l.z].map((c) => c * Math.sqrt(5))).toEqual([expect.closeTo(-1), expect.closeTo(-2), expect.closeTo(0)]);
    expect(dot(l, n)).toBeLessThan(0);
    expect(directionOf(segmentOf(drawing, 'V')).x).toBeCloseTo(Math.SQRT1_2);
    // R = 2(N·L)N − L: L mirrored about N, so −L's mirror image below the surface too.
    const r = directionOf(segmentOf(drawing, 'R'));
    expect([r.x, r.y, r.z].map((c) => c * Math.sqrt(5))).toEqual([expect.closeTo(1), expect.closeTo(-2), expect.closeTo(0)]);
    // All four of one length, half the way to the light (√5 away); the light itself at its place.
    for (const segment of drawing.segments) expect(Math.hypot(...Object.values(minus(segment.to, segment.from)))).toBeCloseTo(Math.sqrt(5) / 2);
    expect(drawing.points).toEqual([
      { at: { x: 0, y: 0, z: 0 }, mark: 'surface' },
      { at: { x: -1, y: -2, z: 0 }, mark: 'light' },
    ]);
    // A piece of the surface: a quad around the point in the plane y = 0, seen from beside the plane of N and L, a little above.
    const [quad] = drawing.shapes;
    expect(quad?.kind === 'quad' && quad.corners.every((corner) => Math.abs(corner.y) < 1e-12)).toBe(true);
    expect(drawing.lookFrom?.z).toBeGreaterThan(0.9);
    expect(drawing.lookFrom?.y).toBeGreaterThan(0);
  });

  it('tells a light in front of the surface from one behind it', () => {
    const [, inTheHighlight] = phongCases(PHONG_EDGES, 0, 3);
    expect(inTheHighlight && lightBehindSurface(inTheHighlight)).toBe(false);
  });
});

describe('a failing run of jittered samples drawn in 3D', () => {
  const runs = pixelSampleRuns([1, 4, 9, 16, 64], 100, 11);
  const grade = (pixelSamples: (n: number, random: () => number) => Point[]) =>
    gradeSamples(
      runs,
      runCases(
        pixelSamples,
        runs.map((run) => run.args),
      ),
      PIXEL_SAMPLES_SIGNIFICANCE,
    ).firstFailure;

  it('draws the pixel, its cells, the run’s points, and fills the crowded and the empty cells', () => {
    // All n points in the first cell: one row and one column of cells wide, not stratified.
    const failure = grade((n, random) => {
      const cells = Math.sqrt(n);
      return Array.from({ length: n }, () => ({ x: random() / cells, y: random() / cells }));
    });
    expect(failure).toMatchObject({ check: 'two-in-a-cell', run: 1 });
    if (!failure || !('points' in failure)) throw new Error('the failure carries the run’s points');
    expect(failure.points).toHaveLength(4);
    const drawing = drawSampleRun(failure);
    expect(drawing?.lookFrom).toEqual({ x: 0, y: 0, z: 1 });
    const fills = drawing?.shapes.map((shape) => (shape.kind === 'quad' ? shape.fill : shape.kind));
    expect(fills).toEqual(['pixel', 'crowded', 'empty', 'empty', 'empty']);
    // 2 × 2 cells: one line across, one line down.
    expect(drawing?.segments.filter((segment) => segment.mark === 'grid')).toHaveLength(2);
    expect(drawing?.points.map((point) => point.mark)).toEqual(['sample', 'sample', 'sample', 'sample']);
    expect(drawing?.points.map((point) => point.at)).toEqual(failure.points.map(({ x, y }) => ({ x, y, z: 0 })));
  });

  it('marks a point outside the pixel as the learner’s wrong answer, drawn at most half a pixel beyond the edge', () => {
    // The textbook loop, with the middle point of the 3 × 3 run far outside the pixel.
    const failure = grade((n, random) => {
      const cells = Math.sqrt(n);
      const points = Array.from({ length: n }, (_, k) => ({ x: ((k % cells) + random()) / cells, y: (Math.floor(k / cells) + random()) / cells }));
      if (n === 9) points[4] = { x: 7, y: 0.5 };
      return points;
    });
    expect(failure).toMatchObject({ check: 'outside-pixel', run: 2 });
    const drawing = failure && drawSampleRun(failure);
    expect(drawing?.points.filter((point) => point.mark === 'got').map((point) => point.at)).toEqual([{ x: 1.5, y: 0.5, z: 0 }]);
    expect(drawing?.points.filter((point) => point.mark === 'sample')).toHaveLength(8);
    // 3 × 3 cells, the middle one empty, as its point went out of the pixel.
    expect(drawing?.segments).toHaveLength(4);
    expect(drawing?.shapes.slice(1)).toEqual([
      {
        kind: 'quad',
        corners: [
          { x: 1 / 3, y: 1 / 3, z: 0 },
          { x: 2 / 3, y: 1 / 3, z: 0 },
          { x: 2 / 3, y: 2 / 3, z: 0 },
          { x: 1 / 3, y: 2 / 3, z: 0 },
        ],
        fill: 'empty',
      },
    ]);
  });

  it('draws the largest run when every run is stratified but the points are not spread within their cells, and nothing for a run with no points', () => {
    const centred = grade((n) => {
      const cells = Math.sqrt(n);
      return Array.from({ length: n }, (_, k) => ({ x: ((k % cells) + 0.5) / cells, y: (Math.floor(k / cells) + 0.5) / cells }));
    });
    expect(centred).toMatchObject({ check: 'uneven-within-cells' });
    const drawing = centred && drawSampleRun(centred);
    expect(drawing?.points).toHaveLength(64);
    expect(drawing?.segments).toHaveLength(14);
    expect(drawing?.shapes).toHaveLength(1);
    expect(drawSampleRun({ check: 'wrong-count', run: 0, got: 0, wanted: 1 })).toBeNull();
  });
});
