import type { LabAnswer, Vec3 } from './code-lab-grading.ts';

/**
 * A failing case as the 3D view draws it (issue 43: each wrong solution "fails on a named case
 * drawn in 3D"), in scene units: the case's rays, the objects it is about, where the tracer's
 * answer puts the ray (`expected`) and where the learner's does (`got`). Each lab says how its
 * cases look (its `drawCase`, lab-drawings.ts); the view draws any lab's the same way.
 */
export type CaseMark = 'ray' | 'expected' | 'got';

/**
 * A segment is one of the case's marks, the surface's normal at the hit (drawn as the case's
 * objects are), one of the shading vectors (toward the light L, toward the eye V, the
 * mirror direction R), or a line of the pixel's grid of cells.
 */
export type SegmentMark = CaseMark | 'normal' | ShadingVector | 'grid';

/** The shading vectors a Phong case draws besides the normal: L toward the light, V toward the eye, R the light's mirror direction. */
export type ShadingVector = 'light' | 'eye' | 'mirror';

export interface CaseSegment {
  from: Vec3;
  to: Vec3;
  /** `ray`: the case's own ray; `expected`/`got`: a path that only one of the two answers takes; `normal`: the surface's normal. */
  mark: SegmentMark;
  /** An arrowhead at `to`: the ray goes on that way. */
  arrow?: boolean;
  /** A name written at `to` (N, L, V, R: the textbook's letters, the same in every language). */
  label?: string;
}

/**
 * A point: the tracer's answer (`expected`), the learner's (`got`), a light, the point being
 * shaded (`surface`), or one of the learner's samples in a pixel (`sample`).
 */
export interface CasePoint {
  at: Vec3;
  mark: Exclude<CaseMark, 'ray'> | 'light' | 'surface' | 'sample';
}

/**
 * How a flat four-cornered shape is filled: a piece of the surface being shaded (see-through),
 * the pixel (opaque, so the scene behind does not show through the samples), a cell of the
 * pixel with no sample (`empty`) or with more than one (`crowded`).
 */
export type QuadFill = 'surface' | 'pixel' | 'empty' | 'crowded';

/** The objects the case is about, drawn as see-through outlines so the points inside them show; flat quads by their corners, in order around. */
export type CaseShape =
  | { kind: 'sphere'; center: Vec3; radius: number }
  | { kind: 'box'; min: Vec3; max: Vec3 }
  | { kind: 'quad'; corners: [Vec3, Vec3, Vec3, Vec3]; fill: QuadFill };

export interface CaseDrawing {
  segments: CaseSegment[];
  points: CasePoint[];
  shapes: CaseShape[];
  /** A cloud of many points (a random function's answers) is drawn with small ones, so that each shows and where they crowd. */
  cloud?: boolean;
  /** The direction from the case toward where it reads best (a flat pixel seen face on); without it the view keeps its direction. */
  lookFrom?: Vec3;
}

/** Every point a view must fit to show the whole case: the segments' ends, the points, the shapes' bounding boxes. */
export function caseDrawingExtent(drawing: CaseDrawing): Vec3[] {
  const corners = drawing.shapes.flatMap((shape) => {
    if (shape.kind === 'box') return [shape.min, shape.max];
    if (shape.kind === 'quad') return shape.corners;
    const { center: c, radius: r } = shape;
    return [
      { x: c.x - r, y: c.y - r, z: c.z - r },
      { x: c.x + r, y: c.y + r, z: c.z + r },
    ];
  });
  return [...drawing.segments.flatMap((segment) => [segment.from, segment.to]), ...drawing.points.map((point) => point.at), ...corners];
}

/**
 * The two answers' colours, in the view and in the panel's legend: Okabe & Ito's bluish green
 * and reddish purple, apart for every kind of colour vision and from the ray legend's
 * colours and the levels' orange and yellow objects; their shapes differ too (a ball for the
 * expected point, a diamond for the learner's), so colour is never the only cue.
 */
export const CASE_MARK_COLORS: Readonly<Record<Exclude<CaseMark, 'ray'>, string>> = { expected: '#009E73', got: '#CC79A7' };

/**
 * The shading vectors' colours, from the same palette (Okabe & Ito): orange toward the light
 * (the light's point too), blue toward the eye, sky blue for the mirror direction. Each arrow
 * also carries its letter, so colour is never the only cue.
 */
export const SHADING_VECTOR_COLORS: Readonly<Record<ShadingVector, string>> = { light: '#E69F00', eye: '#0072B2', mirror: '#56B4E9' };

/** A pixel's cells with no sample (sky blue) and with more than one (the learner's reddish purple), in the view and in the legend. */
export const CELL_FILL_COLORS: Readonly<Record<'empty' | 'crowded', string>> = { empty: '#56B4E9', crowded: '#CC79A7' };

const along = (origin: Vec3, direction: Vec3, t: number): Vec3 => ({
  x: origin.x + t * direction.x,
  y: origin.y + t * direction.y,
  z: origin.z + t * direction.z,
});

/**
 * A ray-and-object case (ray–sphere, ray–box): the ray from its origin on to `reach`, the
 * tracer's hit (expected) and the learner's (got), each where its t puts it on the ray. A
 * negative t the learner returned lies behind the origin: a `got` segment leads back to it,
 * so that "t < 0 accepted" is seen as a hit behind the ray's start.
 */
export function drawHitsOnRay(origin: Vec3, direction: Vec3, reach: number, expected: number | null, got: number | null, shapes: CaseShape[]): CaseDrawing {
  const drawing: CaseDrawing = { segments: [{ from: origin, to: along(origin, direction, reach), mark: 'ray', arrow: true }], points: [], shapes };
  if (expected !== null) drawing.points.push({ at: along(origin, direction, expected), mark: 'expected' });
  if (got !== null) {
    drawing.points.push({ at: along(origin, direction, got), mark: 'got' });
    if (got < 0) drawing.segments.push({ from: origin, to: along(origin, direction, got), mark: 'got' });
  }
  return drawing;
}

/** This kind of lab's answers are distances t (or null): anything else has no place on the ray. */
export const distanceOf = (answer: LabAnswer): number | null => (typeof answer === 'number' ? answer : null);

const HIT: Vec3 = { x: 0, y: 0, z: 0 };
/** A learner's vector longer than this (in units of the unit directions) is drawn this long, so a wild answer does not shrink the rest out of sight. */
const LONGEST_GOT = 2;

/**
 * A direction case (mirror, refraction), drawn at a hit point at the origin: the incoming
 * direction d as a ray of length 1 arriving there, the surface's normal from `normal[0]` to
 * `normal[1]`, and from the hit the tracer's outgoing direction (expected) and the learner's
 * (got), each as an arrow with its mark's point at the tip. An answer that is null (no
 * refracted ray) is not drawn; a learner's vector is drawn as long as they made it (up to
 * LONGEST_GOT), so a direction of the wrong length shows as one.
 */
export function drawDirectionsAtHit(d: Vec3, normal: [Vec3, Vec3], expected: LabAnswer, got: LabAnswer): CaseDrawing {
  const drawing: CaseDrawing = {
    segments: [
      { from: along(HIT, d, -1), to: HIT, mark: 'ray', arrow: true },
      { from: normal[0], to: normal[1], mark: 'normal' },
    ],
    points: [],
    shapes: [],
  };
  const outgoing = (answer: LabAnswer, mark: 'expected' | 'got') => {
    if (!isVector(answer)) return;
    const length = Math.hypot(answer.x, answer.y, answer.z);
    if (length === 0) return;
    const tip = along(HIT, answer, Math.min(1, LONGEST_GOT / length));
    drawing.segments.push({ from: HIT, to: tip, mark, arrow: true });
    drawing.points.push({ at: tip, mark });
  };
  outgoing(expected, 'expected');
  outgoing(got, 'got');
  return drawing;
}

const isVector = (answer: LabAnswer): answer is Vec3 => answer !== null && typeof answer === 'object' && 'x' in answer;
