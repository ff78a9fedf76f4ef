import {
  BufferGeometry,
  CircleGeometry,
  Color,
  DoubleSide,
  Float32BufferAttribute,
  Group,
  Line,
  LineBasicMaterial,
  LineLoop,
  Matrix4,
  Mesh,
  MeshBasicMaterial,
  type Object3D,
  PlaneGeometry,
  Quaternion,
  Vector3,
} from 'three';
import { DEFAULT_SEED } from '../render/render-job.ts';
import type { Scene, SceneObject } from '../scene/scene.ts';
import { CameraRays } from '../tracer/camera-rays.ts';
import { shutterTimes } from '../tracer/shutter-times.ts';
import { RADIANS_PER_DEGREE } from '../util/angles.ts';

const LENS_COLOR = 0x7fd4ff;
const FOCAL_PLANE_COLOR = 0xffd166;
/** A moving object's copies in time are this faint: they show the path, not a second object. */
const GHOST_OPACITY = 0.22;
/** The copy drawn when no k moments are shared or chosen: where the object ends, to show where it goes. */
const END_ONLY = [1];

/** What the gizmos are drawn from, compared to skip rebuilding when nothing of it changed. */
function keyOf(scene: Scene, pixel: readonly [number, number] | null): string {
  const { camera, settings } = scene;
  const moving = scene.objects.filter(isMoving).map((o) => [o.id, o.shape, o.mesh, o.position, o.rotation, o.scale, o.velocity, o.material.color]);
  // The chosen pixel matters only where each pixel has moments of its own.
  const ownMoments = settings.timePattern !== 'grid' && moving.length > 0 ? pixel : null;
  return JSON.stringify([camera, settings.timeSamples, settings.timePattern, ownMoments, moving]);
}

function isMoving(object: SceneObject): boolean {
  return object.velocity.some((component) => component !== 0);
}

/**
 * The moments a moving object's copies are drawn at: only moments the rays are really cast
 * at, from the tracer's own shutterTimes with the screen's seed —
 * - grid: the k moments every pixel's rays are cast at;
 * - jittered or random, with a chosen pixel: the moments of its first sample's rays (each
 *   pixel, and each of its samples, has moments of its own, so choosing another pixel
 *   moves the copies);
 * - otherwise (one time sample, or no pixel to show the moments of): one copy where the
 *   object ends, to show where it goes; the path line stands for the streak.
 */
export function copyMoments(scene: Scene, pixel: readonly [number, number] | null): number[] {
  const { timeSamples: k, timePattern } = scene.settings;
  if (k === 1 || (timePattern !== 'grid' && !pixel)) return END_ONLY;
  const times = new Array<number>(k);
  shutterTimes(timePattern, k, DEFAULT_SEED, pixel?.[0] ?? 0, pixel?.[1] ?? 0, 0, times);
  return times;
}

/**
 * The drawings of distributed ray tracing (distribution-effects §4):
 * - the camera's lens, a disc of radius `aperture` around the eye facing the view, and
 *   (aperture > 0) the plane in focus as a faint rectangle at `focusDistance`, as wide as
 *   the camera's screen sees there: a selected pixel's lens rays start spread over the disc
 *   and meet on that rectangle;
 * - a moving object's faint copies at the moments of copyMoments (the tracer's fixed
 *   moments for the grid pattern, the chosen pixel's own for jittered and random ones),
 *   with a line along its path.
 * Copies share the geometry of the drawn object (`objectOf`), so nothing is built per shape.
 */
export class DistributionGizmos {
  readonly group = new Group();
  private readonly lens = new Group();
  private readonly focalPlane = new Group();
  private readonly motion = new Group();
  private readonly lensMaterial = new MeshBasicMaterial({ color: LENS_COLOR, transparent: true, opacity: 0.35, side: DoubleSide, depthWrite: false });
  private readonly lensEdgeMaterial = new LineBasicMaterial({ color: LENS_COLOR });
  private readonly planeMaterial = new MeshBasicMaterial({ color: FOCAL_PLANE_COLOR, transparent: true, opacity: 0.07, side: DoubleSide, depthWrite: false });
  private readonly planeEdgeMaterial = new LineBasicMaterial({ color: FOCAL_PLANE_COLOR, transparent: true, opacity: 0.7 });
  private readonly disc = new CircleGeometry(1, 48);
  private readonly discEdge = new BufferGeometry().setFromPoints(circlePoints(48));
  private readonly square = new PlaneGeometry(2, 2);
  private readonly squareEdge = new BufferGeometry().setFromPoints([
    new Vector3(-1, -1, 0),
    new Vector3(1, -1, 0),
    new Vector3(1, 1, 0),
    new Vector3(-1, 1, 0),
  ]);
  /** What the motion group holds and must dispose (its materials and path lines). */
  private owned: { dispose(): void }[] = [];
  private key = '';

  constructor() {
    this.group.name = 'distribution gizmos';
    this.lens.name = 'lens';
    this.focalPlane.name = 'plane in focus';
    this.motion.name = 'copies in time';
    this.lens.add(new Mesh(this.disc, this.lensMaterial), new LineLoop(this.discEdge, this.lensEdgeMaterial));
    this.focalPlane.add(new Mesh(this.square, this.planeMaterial), new LineLoop(this.squareEdge, this.planeEdgeMaterial));
    this.group.add(this.lens, this.focalPlane, this.motion);
  }

  /**
   * Brings the drawings in line with `scene`; `objectOf` gives an object's drawn mesh (for
   * its geometry); `pixel` is the camera screen's chosen pixel, whose moments the copies show
   * when each pixel has its own.
   */
  sync(scene: Scene, objectOf: (id: string) => Object3D | undefined, pixel: readonly [number, number] | null = null): void {
    const key = keyOf(scene, pixel);
    if (key === this.key) return;
    this.key = key;
    this.syncCamera(scene);
    this.syncMotion(scene, objectOf, pixel);
  }

  private syncCamera({ camera }: Scene): void {
    const rays = new CameraRays(camera);
    const open = camera.aperture > 0;
    this.lens.visible = open;
    this.focalPlane.visible = open;
    if (!open) return;
    // Both lie across the view: their local z is along the view direction.
    const turn = new Quaternion().setFromRotationMatrix(basisMatrix(rays));
    this.lens.position.copy(rays.eye);
    this.lens.quaternion.copy(turn);
    this.lens.scale.setScalar(camera.aperture);
    const f = rays.focusDistance;
    const halfHeight = f * Math.tan((camera.fov * RADIANS_PER_DEGREE) / 2);
    const [columns, rows] = camera.pixels;
    this.focalPlane.position.copy(rays.eye).addScaledVector(rays.forward, f);
    this.focalPlane.quaternion.copy(turn);
    this.focalPlane.scale.set(halfHeight * (columns / rows), halfHeight, 1);
  }

  private syncMotion(scene: Scene, objectOf: (id: string) => Object3D | undefined, pixel: readonly [number, number] | null): void {
    for (const item of this.owned) item.dispose();
    this.owned = [];
    this.motion.clear();
    const times = copyMoments(scene, pixel);
    for (const object of scene.objects.filter(isMoving)) {
      const drawn = objectOf(object.id);
      const geometry = drawn instanceof Mesh ? (drawn.geometry as BufferGeometry) : null;
      const color = new Color(...object.material.color);
      const from = new Vector3(...object.position);
      const velocity = new Vector3(...object.velocity);
      const pathGeometry = new BufferGeometry().setAttribute(
        'position',
        new Float32BufferAttribute([...from.toArray(), ...from.clone().add(velocity).toArray()], 3),
      );
      const pathMaterial = new LineBasicMaterial({ color, transparent: true, opacity: 0.8 });
      this.owned.push(pathGeometry, pathMaterial);
      const path = new Line(pathGeometry, pathMaterial);
      path.name = `path of ${object.id}`;
      this.motion.add(path);
      if (!geometry || !drawn) continue;
      const ghostMaterial = new MeshBasicMaterial({ color, transparent: true, opacity: GHOST_OPACITY, depthWrite: false, side: DoubleSide });
      this.owned.push(ghostMaterial);
      for (const time of times) {
        const ghost = new Mesh(geometry, ghostMaterial);
        ghost.name = `${object.id} at τ = ${time.toFixed(2)}`;
        ghost.position.copy(from).addScaledVector(velocity, time);
        ghost.quaternion.copy(drawn.quaternion);
        ghost.scale.copy(drawn.scale);
        this.motion.add(ghost);
      }
    }
  }

  dispose(): void {
    for (const item of this.owned) item.dispose();
    for (const item of [
      this.lensMaterial,
      this.lensEdgeMaterial,
      this.planeMaterial,
      this.planeEdgeMaterial,
      this.disc,
      this.discEdge,
      this.square,
      this.squareEdge,
    ])
      item.dispose();
    this.group.clear();
  }
}

/** The rotation whose x, y, z axes are the camera's right, up and backward (as a three.js camera's). */
function basisMatrix(rays: CameraRays): Matrix4 {
  return new Matrix4().makeBasis(rays.right, rays.up, rays.forward.clone().negate());
}

function circlePoints(segments: number): Vector3[] {
  return Array.from({ length: segments }, (_, i) => new Vector3(Math.cos((i / segments) * 2 * Math.PI), Math.sin((i / segments) * 2 * Math.PI), 0));
}
