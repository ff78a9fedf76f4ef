import type { Vec3 } from './code-lab-grading.ts';

/**
 * A failing case as the 3D view draws it (issue 43: each wrong solution "fails on a named case
 * drawn in 3D"), in scene units: the case's rays, the objects it is about, where the tracer's
 * answer puts the ray (`expected`) and where the learner's does (`got`). Each lab says how its
 * cases look (its `drawCase`, lab-drawings.ts); the view draws any lab's the same way.
 */
export type CaseMark = 'ray' | 'expected' | 'got';

export interface CaseSegment {
  from: Vec3;
  to: Vec3;
  /** `ray`: the case's own ray; `expected`/`got`: a path that only one of the two answers takes. */
  mark: CaseMark;
  /** An arrowhead at `to`: the ray goes on that way. */
  arrow?: boolean;
}

export interface CasePoint {
  at: Vec3;
  mark: Exclude<CaseMark, 'ray'>;
}

/** The objects the case is about, drawn as see-through outlines so the points inside them show. */
export type CaseShape = { kind: 'sphere'; center: Vec3; radius: number };

export interface CaseDrawing {
  segments: CaseSegment[];
  points: CasePoint[];
  shapes: CaseShape[];
}

/** Every point a view must fit to show the whole case: the segments' ends, the points, the shapes' bounding boxes. */
export function caseDrawingExtent(drawing: CaseDrawing): Vec3[] {
  const corners = drawing.shapes.flatMap(({ center: c, radius: r }) => [
    { x: c.x - r, y: c.y - r, z: c.z - r },
    { x: c.x + r, y: c.y + r, z: c.z + r },
  ]);
  return [...drawing.segments.flatMap((segment) => [segment.from, segment.to]), ...drawing.points.map((point) => point.at), ...corners];
}

/**
 * The two answers' colours, in the view and in the panel's legend: Okabe & Ito's bluish green
 * and reddish purple, apart for every kind of colour vision and from the ray legend's
 * colours and the levels' orange and yellow objects; their shapes differ too (a ball for the
 * expected point, a diamond for the learner's), so colour is never the only cue.
 */
export const CASE_MARK_COLORS: Readonly<Record<Exclude<CaseMark, 'ray'>, string>> = { expected: '#009E73', got: '#CC79A7' };
