import { Vector3 } from 'three';
import type { FrameScheduler } from './frame-scheduler.ts';
import type { ViewControls } from './view-controls.ts';
import { copyPose, easeInOutCubic, interpolatePose, type ViewPose } from './view-pose.ts';

/** How long a flight takes: long enough to see where you go, short enough not to wait. */
export const FLIGHT_MS = 800;

/**
 * "Fly to the ray tracer's camera" and back: the user's viewpoint glides (ease in-out) to
 * the tracer camera's eye, target and field of view, so the student sees the scene exactly
 * as the ray tracer does; "back" returns to where the flight started. While the user has
 * not moved since arriving, the view follows the camera when it is edited.
 */
export class CameraFlight {
  private home: ViewPose | null = null;
  private following = false;
  private cancel: (() => void) | null = null;
  private readonly from: ViewPose = { position: new Vector3(), target: new Vector3(), fov: 0 };

  constructor(
    private readonly controls: ViewControls,
    private readonly scheduler: FrameScheduler,
    private readonly changed: (atCamera: boolean) => void,
  ) {}

  /** Whether the view is at (or flying to, or was moved away from) the camera, with a way back. */
  get atCamera(): boolean {
    return this.home !== null;
  }

  /** Whether a flight or glide is under way. */
  get flying(): boolean {
    return this.cancel !== null;
  }

  /** Flies to `camera`; `arrived` runs when the flight ends. */
  flyTo(camera: ViewPose, arrived: () => void): void {
    if (this.home === null) this.home = this.controls.pose;
    this.fly(camera, () => {
      this.following = true;
      arrived();
    });
    this.changed(true);
  }

  /** Glides to `pose` as the user's own new viewpoint (not the camera's: no way back, no following). */
  glide(pose: ViewPose): void {
    this.following = false;
    this.fly(pose, () => {});
  }

  /** Flies back to where the first flight to the camera started. */
  back(): void {
    const home = this.home;
    if (!home) return;
    this.home = null;
    this.following = false;
    this.fly(home, () => {});
    this.changed(false);
  }

  /** Drops the way back (a new scene: the old viewpoint means nothing there). */
  forget(): void {
    this.cancel?.();
    this.following = false;
    if (this.home === null) return;
    this.home = null;
    this.changed(false);
  }

  /** The camera was edited: stay in its eye if the user has not looked around since arriving. */
  cameraMoved(camera: ViewPose): void {
    if (this.following && this.cancel === null) this.controls.setPose(camera);
  }

  /** The user moved the view: stop following the camera (but keep the way back). */
  userMoved(): void {
    this.following = false;
  }

  dispose(): void {
    this.cancel?.();
  }

  private fly(to: ViewPose, landed: () => void): void {
    this.cancel?.();
    this.controls.settle();
    copyPose(this.controls.pose, this.from);
    const destination = copyPose(to);
    const pose = copyPose(to);
    let start: number | null = null;
    this.controls.enabled = false;
    const remove = this.scheduler.addAnimator((time) => {
      start ??= time;
      const t = (time - start) / FLIGHT_MS;
      this.controls.setPose(interpolatePose(this.from, destination, easeInOutCubic(t), pose));
      if (t < 1) return true;
      remove();
      this.finish();
      landed();
      return false;
    });
    this.cancel = () => {
      remove();
      this.finish();
    };
  }

  private finish(): void {
    this.cancel = null;
    this.controls.enabled = true;
  }
}
