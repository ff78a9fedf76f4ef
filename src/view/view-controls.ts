import { MOUSE, type PerspectiveCamera, TOUCH } from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import type { LabAction } from '../lab-state/lab-action.ts';
import type { FrameScheduler } from './frame-scheduler.ts';
import { copyPose, easeInOutCubic, gestureActions, type ViewPose } from './view-pose.ts';
import { RADIANS_PER_DEGREE } from '../util/angles.ts';

/**
 * A gesture is over when the view has been still this long: one wheel spin or one run of
 * key repeats is one gesture, not forty (the quest engine counts gestures, not frames).
 */
const SETTLE_MS = 350;
/** A toolbar step glides over this long instead of jumping, so the eye can follow it. */
const STEP_MS = 220;

/**
 * Orbit, pan and zoom of the user's viewpoint: three.js's OrbitControls for mouse and touch
 * (one finger orbits, two pan and pinch-zoom), and the same moves as methods for keys and
 * on-screen buttons (trackpads without a wheel). Reports each gesture once, when it has
 * settled, as view.orbited / view.panned / view.zoomed.
 */
export class ViewControls {
  readonly orbit: OrbitControls;
  private before: ViewPose | null = null;
  private settleTimer: ReturnType<typeof setTimeout> | null = null;

  constructor(
    private readonly camera: PerspectiveCamera,
    private readonly canvas: HTMLCanvasElement,
    private readonly scheduler: FrameScheduler,
    private readonly report: (action: LabAction) => void,
  ) {
    this.orbit = new OrbitControls(camera, canvas);
    this.orbit.minDistance = 0.3;
    this.orbit.maxDistance = 80;
    this.orbit.mouseButtons = { LEFT: MOUSE.ROTATE, MIDDLE: MOUSE.DOLLY, RIGHT: MOUSE.PAN };
    this.orbit.touches = { ONE: TOUCH.ROTATE, TWO: TOUCH.DOLLY_PAN };
    this.orbit.addEventListener('change', () => scheduler.requestRender());
    this.orbit.addEventListener('start', () => this.gestureStarted());
    this.orbit.addEventListener('end', () => this.gestureMoved());
  }

  /** The current viewpoint (a copy). */
  get pose(): ViewPose {
    return copyPose({ position: this.camera.position, target: this.orbit.target, fov: this.camera.fov });
  }

  /** Puts the viewpoint at `pose` without reporting a gesture (a camera flight). */
  setPose(pose: ViewPose): void {
    this.camera.position.copy(pose.position);
    this.orbit.target.copy(pose.target);
    if (this.camera.fov !== pose.fov) {
      this.camera.fov = pose.fov;
      this.camera.updateProjectionMatrix();
    }
    this.orbit.update();
    this.scheduler.requestRender();
  }

  set enabled(enabled: boolean) {
    this.orbit.enabled = enabled;
  }

  /** Moves the viewpoint around the target: +dx to the right, +dy up, in degrees. */
  orbitBy(dxDeg: number, dyDeg: number, glide: boolean): void {
    this.step(glide, (share) => {
      this.orbit.rotateLeft(-dxDeg * RADIANS_PER_DEGREE * share);
      this.orbit.rotateUp(dyDeg * RADIANS_PER_DEGREE * share);
    });
  }

  /** Slides the viewpoint and its target: +dx right, +dy up, as shares of the visible height at the target. */
  panBy(dx: number, dy: number, glide: boolean): void {
    const height = this.canvas.clientHeight;
    if (height === 0) return;
    this.step(glide, (share) => this.orbit.pan(-dx * height * share, dy * height * share));
  }

  /** Moves toward the target (factor > 1) or away from it (< 1). */
  zoomBy(factor: number, glide: boolean): void {
    this.step(glide, (share) => this.orbit.dollyOut(factor ** share));
  }

  dispose(): void {
    if (this.settleTimer !== null) clearTimeout(this.settleTimer);
    this.orbit.dispose();
  }

  /**
   * Applies a move now, or spread over STEP_MS with ease-in-out: each frame applies the
   * share of the whole move that the eased clock advanced by.
   */
  private step(glide: boolean, apply: (share: number) => void): void {
    this.gestureStarted();
    if (!glide) {
      apply(1);
      this.gestureMoved();
      return;
    }
    let start: number | null = null;
    let done = 0;
    const remove = this.scheduler.addAnimator((time) => {
      start ??= time;
      const eased = easeInOutCubic((time - start) / STEP_MS);
      apply(eased - done);
      done = eased;
      if (eased < 1) return true;
      remove();
      this.gestureMoved();
      return false;
    });
  }

  /** Reports a gesture still settling now (before a camera flight moves the view). */
  settle(): void {
    if (this.settleTimer !== null) clearTimeout(this.settleTimer);
    this.settleTimer = null;
    const before = this.before;
    this.before = null;
    if (before) for (const action of gestureActions(before, this.pose)) this.report(action);
  }

  private gestureStarted(): void {
    // A new gesture right after another (a second wheel spin) continues it.
    if (this.settleTimer !== null) clearTimeout(this.settleTimer);
    this.settleTimer = null;
    this.before ??= this.pose;
  }

  /** Waits for the view to settle, then reports what the gesture did. */
  private gestureMoved(): void {
    if (this.settleTimer !== null) clearTimeout(this.settleTimer);
    this.settleTimer = setTimeout(() => this.settle(), SETTLE_MS);
  }
}
