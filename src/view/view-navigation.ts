import { msg } from '@lit/localize';
import { type PerspectiveCamera, Vector3 } from 'three';
import type { LabAction } from '../lab-state/lab-action.ts';
import type { ViewLook } from '../lab-state/lab-state.ts';
import type { Store } from '../lab-state/store.ts';
import type { Vec3 } from '../scene/scene.ts';
import { CameraFlight } from './fly-to-camera.ts';
import type { FrameScheduler } from './frame-scheduler.ts';
import { VIEW_FOV } from './view-drawing.ts';
import { LookFollower } from './view-look.ts';
import { cameraViewFov, framingPose, framingPoseAbove, type ViewPose } from './view-pose.ts';
import { ViewControls } from './view-controls.ts';

/** Toolbar steps: one press orbits 15°, pans a tenth of the view, zooms 1.25×. */
const BUTTON_ORBIT_DEG = 15;
const BUTTON_PAN = 0.1;
const BUTTON_ZOOM = 1.25;

/** What navigation needs of the rest of the 3D view. */
export interface NavigatedView {
  /** The world points a declared view fits for `name` (view-look.ts). */
  pointsOf(name: string): Vec3[];
  /** The chosen pixel's whole ray path with the camera it starts at, or null while its trace is not in. */
  pixelRayPoints(): Vec3[] | null;
  /** Reports a gesture or an arrival to the store (a refusal is shown by the view). */
  dispatch(action: LabAction): void;
  /** The view went to the ray tracer's camera (true) or came away with no way back (false). */
  flightChanged(atCamera: boolean): void;
  /** Something to tell the user (a toast). */
  message(text: string): void;
}

/**
 * Where the user looks from and how they get there: orbit, pan and zoom (mouse, touch, keys
 * and toolbar: view-controls.ts), the flight to the ray tracer's camera and back
 * (fly-to-camera.ts), a level's declared look (view-look.ts), and framing the whole scene or
 * the chosen pixel's rays into the part of the view no panel covers. One concept apart from
 * LabView, which draws the scene and handles selection.
 */
export class ViewNavigation {
  private readonly controls: ViewControls;
  private readonly flight: CameraFlight;
  private readonly look: LookFollower;
  private coveredBottom = 0;

  /** Made after the transform gizmo: its pointerdown must claim a drag before the orbit controls see it. */
  constructor(
    private readonly camera: PerspectiveCamera,
    private readonly canvas: HTMLCanvasElement,
    scheduler: FrameScheduler,
    private readonly store: Store,
    private readonly view: NavigatedView,
  ) {
    this.controls = new ViewControls(camera, canvas, scheduler, (action) => view.dispatch(action));
    this.controls.orbit.addEventListener('start', () => {
      this.flight.userMoved();
      this.look.userMoved();
    });
    this.flight = new CameraFlight(this.controls, scheduler, (atCamera) => view.flightChanged(atCamera));
    this.look = new LookFollower({
      pointsOf: (name) => view.pointsOf(name),
      pixelRayPoints: () => view.pixelRayPoints(),
      pose: () => this.controls.pose,
      fov: VIEW_FOV,
      aspect: () => this.camera.aspect,
      visibleShare: () => this.visibleShare(),
      moveTo: (pose, glide) => {
        if (glide) return this.flight.glide(pose);
        this.flight.forget();
        this.controls.setPose(pose);
      },
      throughCamera: () => this.flight.flyTo(this.tracerCameraPose(), () => {}),
    });
  }

  /** Whether the view is still on its way: a flight or glide under way, or a framing waiting for its pixel's rays. */
  get moving(): boolean {
    return this.flight.flying || this.look.waitingForRays;
  }

  /** Whether the view is at the ray tracer's camera, or has a way back to where it was. */
  get atCamera(): boolean {
    return this.flight.atCamera;
  }

  /** While a gizmo handle is dragged the orbit controls must not move the view. */
  pauseGestures(paused: boolean): void {
    this.controls.enabled = !paused;
  }

  /** Orbits the view: +dx moves the eye right around the target, +dy up; `glide` spreads it over a few frames. */
  orbit(dxDeg = BUTTON_ORBIT_DEG, dyDeg = 0, glide = true): void {
    this.controls.orbitBy(dxDeg, dyDeg, glide);
  }

  /** Pans: shares of the visible height, +dx right, +dy up. */
  pan(dx = BUTTON_PAN, dy = 0, glide = true): void {
    this.controls.panBy(dx, dy, glide);
  }

  /** Zooms: factor > 1 moves closer. */
  zoom(factor = BUTTON_ZOOM, glide = true): void {
    this.controls.zoomBy(factor, glide);
  }

  /** Glides to the ray tracer's camera (eye, target, fov); reports view.flew-to-camera on arrival. */
  flyToCamera(): void {
    this.flight.flyTo(this.tracerCameraPose(), () => this.view.dispatch({ type: 'view.flew-to-camera' }));
  }

  /** Glides back to where the view was before flying to the camera. */
  flyBack(): void {
    this.flight.back();
  }

  /**
   * "Show its rays": glides, from the side the view looks from now, to where the chosen
   * pixel's whole ray path (and the camera it starts at) fits the view.
   */
  showPixelRays(): void {
    const points = this.view.pixelRayPoints();
    if (!points) {
      this.view.message(msg('Choose a pixel first: its rays are what this shows.'));
      return;
    }
    const pose = this.controls.pose;
    const direction = pose.position.clone().sub(pose.target).normalize();
    this.flight.glide(framingPoseAbove(points, VIEW_FOV, this.camera.aspect, direction, this.visibleShare()));
  }

  /** Glides to where every one of `points` fits the view, looking from `from` (a direction toward the eye) or else from where the view looks now. */
  showPoints(points: readonly Vec3[], from?: Vec3): void {
    if (points.length === 0) return;
    const pose = this.controls.pose;
    const direction = from ? new Vector3(...from).normalize() : pose.position.clone().sub(pose.target).normalize();
    this.flight.glide(framingPoseAbove(points, VIEW_FOV, this.camera.aspect, direction, this.visibleShare()));
  }

  /** How much of the canvas's bottom (CSS px) panels over the view cover: framing fits what it shows into the part above. */
  setCoveredBottom(px: number): void {
    this.coveredBottom = Math.max(0, px);
  }

  private visibleShare(): number {
    const height = this.canvas.clientHeight;
    // Never frame into a sliver: below 40 % the panels cover the view and it is better whole.
    return height > 0 ? Math.max(0.4, 1 - this.coveredBottom / height) : 1;
  }

  /** Looks at the whole scene (objects, lights and the tracer's camera) from the front left, above. */
  frameScene(): void {
    const { objects, lights, camera } = this.store.state.scene;
    const centre = [...objects.map((o) => o.position), camera.position];
    const pose = framingPose(centre, [...centre, ...lights.map((l) => l.position)], this.camera.fov, this.camera.aspect);
    this.controls.setPose(pose);
  }

  /** Follows a declared look (view-look.ts): gliding there, or at once. */
  follow(look: ViewLook | null, glide: boolean): void {
    this.look.follow(look, glide);
  }

  /** A new trace is in: a framing of a pixel's rays fits them again. */
  raysArrived(): void {
    this.look.raysArrived();
  }

  /** A new scene: no way back to a flight's start, and the whole scene in view. */
  sceneLoaded(): void {
    this.flight.forget();
    this.frameScene();
  }

  /** The tracer's camera was edited: a view at it follows. */
  cameraEdited(): void {
    this.flight.cameraMoved(this.tracerCameraPose());
  }

  /** At the tracer's camera, wide enough to show all of its screen of pixels in this view's shape. */
  private tracerCameraPose(): ViewPose {
    const { position, target, fov, pixels } = this.store.state.scene.camera;
    return { position: new Vector3(...position), target: new Vector3(...target), fov: cameraViewFov(fov, pixels[0] / pixels[1], this.camera.aspect) };
  }

  dispose(): void {
    this.flight.dispose();
    this.controls.dispose();
  }
}
