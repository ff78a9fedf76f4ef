import { Box3, Spherical, Vector3 } from 'three';
import type { LabAction } from '../lab-state/lab-action.ts';
import type { Vec3 } from '../scene/scene.ts';

/** Where the user's viewpoint is: the eye, the point it orbits around, its vertical fov in degrees. */
export interface ViewPose {
  position: Vector3;
  target: Vector3;
  fov: number;
}

export function copyPose(from: ViewPose, into: ViewPose = { position: new Vector3(), target: new Vector3(), fov: 0 }): ViewPose {
  into.position.copy(from.position);
  into.target.copy(from.target);
  into.fov = from.fov;
  return into;
}

type ViewAction = Extract<LabAction, { type: 'view.orbited' | 'view.panned' | 'view.zoomed' }>;

/**
 * Changes smaller than these are not a gesture: a click that wobbled a pixel, or float noise
 * from OrbitControls re-deriving the pose (relative to the orbit radius, so scale-free).
 */
const ANGLE_EPSILON = 1e-4;
const RELATIVE_EPSILON = 1e-4;

/**
 * What a gesture did to the view, as the facts the quest engine listens for: the target
 * moved (pan), the distance to it changed (zoom), the direction from it turned (orbit).
 * A two-finger touch gesture can pan and zoom at once, so this is a list.
 */
export function gestureActions(before: ViewPose, after: ViewPose): ViewAction[] {
  const actions: ViewAction[] = [];
  sphericalBefore.setFromVector3(offset.subVectors(before.position, before.target));
  sphericalAfter.setFromVector3(offset.subVectors(after.position, after.target));
  const radius = Math.max(sphericalBefore.radius, 1e-9);
  const turned =
    Math.abs(angleBetween(sphericalBefore.theta, sphericalAfter.theta)) > ANGLE_EPSILON || Math.abs(sphericalBefore.phi - sphericalAfter.phi) > ANGLE_EPSILON;
  if (turned) actions.push({ type: 'view.orbited' });
  if (before.target.distanceTo(after.target) > RELATIVE_EPSILON * radius) actions.push({ type: 'view.panned' });
  if (Math.abs(sphericalAfter.radius - sphericalBefore.radius) > RELATIVE_EPSILON * radius) actions.push({ type: 'view.zoomed' });
  return actions;
}

/** The signed difference of two azimuths, wrapped into (−π, π]. */
function angleBetween(a: number, b: number): number {
  const d = (b - a) % (2 * Math.PI);
  return d > Math.PI ? d - 2 * Math.PI : d <= -Math.PI ? d + 2 * Math.PI : d;
}

/** Slow start, slow end (cubic): a camera flight that neither jolts nor brakes hard. */
export function easeInOutCubic(t: number): number {
  const c = Math.min(1, Math.max(0, t));
  return c < 0.5 ? 4 * c * c * c : 1 - (-2 * c + 2) ** 3 / 2;
}

/** The pose a fraction `t` (0..1, already eased) of the way from `from` to `to`. */
export function interpolatePose(from: ViewPose, to: ViewPose, t: number, out: ViewPose): ViewPose {
  out.position.lerpVectors(from.position, to.position, t);
  out.target.lerpVectors(from.target, to.target, t);
  out.fov = from.fov + (to.fov - from.fov) * t;
  return out;
}

/** Room left around the tracer's screen when the view flies to its camera (10 % each way). */
const CAMERA_VIEW_MARGIN = 1.1;

/**
 * The 3D view's vertical field of view (degrees) at the tracer's camera, so that the whole
 * screen of pixels fits in both directions, with a margin: the tracer frames `fovDeg`
 * vertically and `fovDeg` widened by its screen's aspect horizontally (camera-rays.ts), and a
 * view narrower than that screen must open up its vertical angle to show every column.
 */
export function cameraViewFov(fovDeg: number, screenAspect: number, viewAspect: number): number {
  const tanHalf = Math.tan((fovDeg * Math.PI) / 360) * CAMERA_VIEW_MARGIN * Math.max(1, screenAspect / viewAspect);
  return (Math.atan(tanHalf) * 360) / Math.PI;
}

/** The side the lab looks from at first: front left, above (the tracer's camera usually looks down −Z). */
const FRAMING_DIRECTION = new Vector3(-0.5, 0.45, 0.74).normalize();

/**
 * A first view of a scene: looking at the middle of `centrePoints` (objects and the tracer's
 * camera) from the front left and above (or from `direction`, a unit vector from the target
 * towards the eye), far enough back that every point of `allPoints` (lights too) fits in the
 * vertical fov and, for a narrow view, the horizontal one.
 */
export function framingPose(
  centrePoints: readonly Vec3[],
  allPoints: readonly Vec3[],
  fov: number,
  aspect: number,
  direction: Vector3 = FRAMING_DIRECTION,
): ViewPose {
  const box = new Box3();
  for (const point of centrePoints) box.expandByPoint(offset.set(...point));
  const target = box.isEmpty() ? new Vector3() : box.getCenter(new Vector3());
  let radius = 1;
  for (const point of allPoints) radius = Math.max(radius, offset.set(...point).distanceTo(target));
  const halfFov = (fov * Math.PI) / 360;
  // The tighter of the vertical half-angle and the horizontal one (narrow views). A sphere of
  // radius r fits a cone of half-angle a from distance r / sin(a) (r / tan(a) would cut off
  // the points on the near side).
  const half = Math.min(halfFov, Math.atan(Math.tan(halfFov) * aspect));
  const distance = radius / Math.sin(half);
  return { position: target.clone().addScaledVector(direction, distance), target, fov };
}

/**
 * framingPose for a view whose lower part is covered by panels: everything fits in the top
 * `visibleShare` (0..1] of its height and is centred there. The band has the vertical fov
 * 2·atan(tan(fov/2)·share) and the aspect aspect/share; framing it from distance d puts the
 * framed centre in the middle of the canvas, and panning down by (1 − share)·d·tan(fov/2)
 * (half the covered height at that depth) moves it to the middle of the band.
 */
export function framingPoseAbove(points: readonly Vec3[], fov: number, aspect: number, direction: Vector3, visibleShare: number): ViewPose {
  const share = Math.min(1, Math.max(0.05, visibleShare));
  const tanHalf = Math.tan((fov * Math.PI) / 360);
  const bandFov = (Math.atan(tanHalf * share) * 360) / Math.PI;
  const pose = framingPose(points, points, bandFov, aspect / share, direction);
  const distance = pose.position.distanceTo(pose.target);
  const up = new Vector3(0, 1, 0).addScaledVector(direction, -direction.y);
  if (up.lengthSq() < 1e-9) up.set(0, 0, -1); // looking straight down: "up" on screen is −z
  up.normalize().multiplyScalar((1 - share) * distance * tanHalf);
  pose.position.sub(up);
  pose.target.sub(up);
  pose.fov = fov;
  return pose;
}

const offset = new Vector3();
const sphericalBefore = new Spherical();
const sphericalAfter = new Spherical();
