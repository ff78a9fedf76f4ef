import { type Object3D, Raycaster, Vector3 } from 'three';
import type { Vec3 } from '../scene/scene.ts';
import type { RayNode } from '../tracer/ray-tree.ts';

/**
 * What a task's evidence ray looks like in the 3D view (docs/levels.md, "Evidence"), for the
 * browser test that checks a task's start view shows it: points along the ray as drawn, each
 * where it lands on the canvas and whether an opaque object hides it from the eye. The test
 * adds up the length that shows (on the canvas, not hidden, under no panel).
 */

/** Points looked at along a ray: a 10 m miss is sampled every 20 cm, a 1 m ray every 2 cm. */
export const EVIDENCE_SAMPLES = 50;

export interface EvidencePoint {
  /** CSS px from the canvas's top-left corner. */
  x: number;
  y: number;
  hidden: boolean;
}

/**
 * Points along `node` from its origin to its drawn end (a ray that hit nothing is drawn its
 * whole 10 m), projected by `project` (null: behind the eye, left out) and tested by `hidden`.
 */
export function rayEvidence(node: RayNode, project: (point: Vec3) => { x: number; y: number } | null, hidden: (point: Vec3) => boolean): EvidencePoint[] {
  const points: EvidencePoint[] = [];
  for (let i = 0; i <= EVIDENCE_SAMPLES; i++) {
    const along = (node.length * i) / EVIDENCE_SAMPLES;
    const point = [0, 1, 2].map((axis) => node.origin[axis] + node.direction[axis] * along) as Vec3;
    const place = project(point);
    if (place) points.push({ ...place, hidden: hidden(point) });
  }
  return points;
}

/**
 * How near a surface a point may lie behind it and still count as on it (metres, plus a share
 * of its distance): a ray's end on the ball it hits is not hidden by that ball.
 */
const ON_SURFACE = 0.01;
const ON_SURFACE_SHARE = 0.002;

const raycaster = new Raycaster();
// Only surfaces hide: three's default would count any line within 1 m as in the way.
raycaster.params.Line.threshold = 0;
raycaster.params.Points.threshold = 0;
const towards = new Vector3();

/**
 * Whether something opaque among `roots` lies between `eye` and `point`: a see-through object
 * (glass, drawn at partial opacity) shows what is behind it, and hides nothing here.
 */
export function hiddenFrom(eye: Vector3, point: Vec3, roots: Object3D[]): boolean {
  towards.set(...point).sub(eye);
  const distance = towards.length();
  if (distance < ON_SURFACE) return false;
  raycaster.set(eye, towards.normalize());
  raycaster.far = distance - ON_SURFACE - ON_SURFACE_SHARE * distance;
  return raycaster.intersectObjects(roots, true).some(({ object }) => shownOpaque(object));
}

function shownOpaque(object: Object3D): boolean {
  for (let node: Object3D | null = object; node; node = node.parent) if (!node.visible) return false;
  const material = (object as Object3D & { material?: { transparent?: boolean } | { transparent?: boolean }[] }).material;
  const materials = Array.isArray(material) ? material : material ? [material] : [];
  return materials.length > 0 && materials.every((one) => one.transparent !== true);
}
