import { Box3, type Object3D, Vector3 } from 'three';
import type { ViewLook } from '../lab-state/lab-state.ts';
import type { Scene, Vec3 } from '../scene/scene.ts';
import { framedRaysPixel } from '../lab-state/framed-rays.ts';
import { framingPoseAbove, type ViewPose } from './view-pose.ts';

/** What following a declared view's look needs of the 3D view. */
export interface LookStage {
  /**
   * The world points a framed name stands for (an object's box, a light, the camera with its
   * screen, a named pixel's rays after their first hit: framed-rays.ts); none for an unknown
   * name, or a pixel not traced yet.
   */
  pointsOf(name: string): Vec3[];
  /** The chosen pixel's whole ray path with the camera it starts at, or null while its trace is not in. */
  pixelRayPoints(): Vec3[] | null;
  /** Where the view is now. */
  pose(): ViewPose;
  /** The view's own field of view (degrees) and aspect, which a framing fits. */
  fov: number;
  aspect(): number;
  /** The share of the view's height, from the top, that no panel covers: what a framing fits into. */
  visibleShare(): number;
  /** Puts the view at `pose`: gliding there, or at once. */
  moveTo(pose: ViewPose, glide: boolean): void;
  /** Looks through the ray tracer's camera, as "Camera view" does, without reporting it as the learner's doing. */
  throughCamera(): void;
}

/** Whether `name` frames a pixel's rays: the chosen pixel's ("pixel-rays") or a named one's ("rays:3,1"). */
function namesRays(name: string): boolean {
  return name === 'pixel-rays' || framedRaysPixel(name) !== null;
}

/**
 * How long a framing of a pixel's rays waits for that pixel's trace and follows newer
 * traces: a level's first screen is traced a fraction of a second after it opens, and a
 * trace of the scene before may land first.
 */
export const PIXEL_RAYS_WAIT_MS = 3000;

/**
 * The 3D view following a level's or task's declared look (docs/levels.md, "Views"): it
 * glides to fit what the look names, from the side it names or the side it looks from now,
 * into the part of the view that no panel covers.
 * A look that frames a pixel's rays (the chosen one's, or a named one's) frames them again
 * as their trace comes in, until the learner moves the view or PIXEL_RAYS_WAIT_MS have passed.
 */
export class LookFollower {
  private waiting: { look: ViewLook; until: number } | null = null;

  constructor(
    private readonly stage: LookStage,
    private readonly now: () => number = () => performance.now(),
  ) {}

  /** Whether a framing still waits for its pixel's rays. */
  get waitingForRays(): boolean {
    return this.waiting !== null && this.now() < this.waiting.until;
  }

  /** Follows `look` (null: nothing to do); `glide` false jumps there (a level's first view). */
  follow(look: ViewLook | null, glide: boolean): void {
    this.waiting = null;
    if (!look) return;
    if (look.throughCamera) return this.stage.throughCamera();
    if (!look.frame) return;
    if (look.frame.some(namesRays)) this.waiting = { look, until: this.now() + PIXEL_RAYS_WAIT_MS };
    this.frame(look, glide);
  }

  /** New traces are in: a framing that waits for them frames again. */
  raysArrived(): void {
    if (!this.waiting) return;
    if (this.now() >= this.waiting.until) {
      this.waiting = null;
      return;
    }
    this.frame(this.waiting.look, true);
  }

  /** The learner took the view: nothing framed waits any longer. */
  userMoved(): void {
    this.waiting = null;
  }

  private frame(look: ViewLook, glide: boolean): void {
    const points = (look.frame ?? []).flatMap((name) => (name === 'pixel-rays' ? (this.stage.pixelRayPoints() ?? []) : this.stage.pointsOf(name)));
    if (points.length === 0) return;
    const pose = this.stage.pose();
    const direction = look.from ? new Vector3(...look.from).normalize() : pose.position.clone().sub(pose.target).normalize();
    this.stage.moveTo(framingPoseAbove(points, this.stage.fov, this.stage.aspect(), direction, this.stage.visibleShare()), glide);
  }
}

/**
 * The points a framed name stands for: an object's drawn box (a plane only its centre: a
 * floor would fill any view), a light's drawn shape (a spot's cone shows where it points,
 * the very thing a task may ask about) or its position, the tracer's camera with its screen.
 * `drawn` gives an object's or a light's drawing by id.
 */
export function framedPoints(name: string, scene: Scene, drawn: (id: string) => Object3D | undefined, cameraRig: Object3D): Vec3[] {
  if (name === 'camera') return [scene.camera.position, ...boxCorners(cameraRig)];
  const light = scene.lights.find((candidate) => candidate.id === name);
  if (light) return [light.position, ...boxCorners(drawn(name))];
  const object = scene.objects.find((candidate) => candidate.id === name);
  if (!object) return [];
  const corners = object.shape === 'plane' ? [] : boxCorners(drawn(name));
  return corners.length > 0 ? corners : [object.position];
}

function boxCorners(object: Object3D | undefined): Vec3[] {
  if (!object) return [];
  const box = new Box3().setFromObject(object);
  if (box.isEmpty()) return [];
  const { min, max } = box;
  return [0, 1, 2, 3, 4, 5, 6, 7].map((corner) => [corner & 1 ? max.x : min.x, corner & 2 ? max.y : min.y, corner & 4 ? max.z : min.z]);
}
