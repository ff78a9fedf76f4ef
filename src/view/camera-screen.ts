import {
  BoxGeometry,
  BufferGeometry,
  CylinderGeometry,
  DataTexture,
  DoubleSide,
  Float32BufferAttribute,
  Group,
  LineBasicMaterial,
  LineSegments,
  Mesh,
  MeshBasicMaterial,
  MeshPhongMaterial,
  NearestFilter,
  PlaneGeometry,
  Points,
  PointsMaterial,
  Shape,
  ShapeGeometry,
  Path,
} from 'three';
import type { LabState } from '../lab-state/lab-state.ts';
import type { ScreenRays } from '../render/screen-rays.ts';
import type { Camera, RenderSettings } from '../scene/scene.ts';
import { CameraRays } from '../tracer/camera-rays.ts';
import { setPickTag, type PickTag } from './picking.ts';
import { useTracerFalloff } from './raster-falloff.ts';
import { cameraRigQuaternion, samplePoints, type ScreenGrid, screenGrid } from './screen-grid.ts';

/** A pixel not traced yet: a neutral slate, so the grid reads as "empty" rather than black. */
const UNTRACED = [92, 101, 115];
const BODY_COLOR = 0x56606e;
const BODY_EMISSIVE = 0x2a313b;
const FRUSTUM_COLOR = 0x2b3340;
const GRID_COLOR = 0x11151b;
const SELECTED_COLOR = 0xffb020;
/** The screen is slightly see-through, so the scene behind it still shows… */
const SCREEN_OPACITY = 0.88;
/** …and mostly see-through from the camera's own eye: the scene seen through its pixel grid. */
const SCREEN_OPACITY_FROM_EYE = 0.4;
/** Overlays float this share of the screen distance in front of it, above the depth test's noise. */
const LIFT = 0.003;

/** What the screen drawing depends on, from the lab state. */
export type CameraScreenState = Pick<LabState, 'selectedPixel'> & {
  camera: Camera;
  settings: Pick<RenderSettings, 'supersampling' | 'samplePattern'>;
  showSamplePoints: boolean;
};

/**
 * The ray tracer's camera as the lab draws it: a small camera body, frustum lines, and in
 * front of it the SCREEN, a grid of camera.pixels cells at screenDistance showing each
 * pixel's traced colour (one texel per pixel, nearest filtering), the selected pixel
 * outlined, and on request the s×s sub-pixel sample points. The rig's local frame is the
 * camera's: x right, y up, looking down −z (see screen-grid.ts).
 */
export class CameraScreen {
  readonly rig = new Group();
  /** The camera's body (the selection outline wraps it). */
  readonly body = new Group();
  private readonly plane = new Group();
  private readonly screenTag: Extract<PickTag, { kind: 'screen' }> = { kind: 'screen', columns: 1, rows: 1 };
  private readonly screenMaterial = new MeshBasicMaterial({ transparent: true, opacity: SCREEN_OPACITY, side: DoubleSide });
  private texture = untracedTexture(1, 1);
  private readonly frustum = new LineSegments(
    new BufferGeometry().setAttribute('position', new Float32BufferAttribute(new Float32Array(8 * 3), 3)),
    new LineBasicMaterial({ color: FRUSTUM_COLOR, transparent: true, opacity: 0.55 }),
  );
  private readonly grid = new LineSegments(new BufferGeometry(), new LineBasicMaterial({ color: GRID_COLOR, transparent: true, opacity: 0.55 }));
  private readonly strata = new LineSegments(new BufferGeometry(), new LineBasicMaterial({ color: GRID_COLOR, transparent: true, opacity: 0.3 }));
  private readonly selected = new Mesh(frameGeometry(0.14), new MeshBasicMaterial({ color: SELECTED_COLOR, side: DoubleSide }));
  private readonly samples = new Points(new BufferGeometry(), new PointsMaterial({ map: dotTexture(), alphaTest: 0.5, sizeAttenuation: true }));
  private readonly owned: { dispose(): void }[] = [];
  private gridKey = '';
  private samplesKey = '';
  private current: ScreenGrid = screenGrid({ position: [0, 0, 1], target: [0, 0, 0], fov: 45, pixels: [1, 1], screenDistance: 1, aperture: 0, lensSamples: 1 });

  constructor() {
    this.rig.name = 'ray tracer camera';
    setPickTag(this.body, { kind: 'camera' });
    setPickTag(this.frustum, { kind: 'camera' });
    // Partly self-lit, so the body reads as a dark grey shape whatever the scene's lights do.
    const bodyMaterial = new MeshPhongMaterial({ color: BODY_COLOR, emissive: BODY_EMISSIVE, specular: 0x444444, shininess: 40 });
    useTracerFalloff(bodyMaterial);
    const box = new BoxGeometry(0.22, 0.16, 0.26).translate(0, 0, 0.13);
    // The lens: a short cylinder along −z, in front of the eye.
    const lens = new CylinderGeometry(0.06, 0.075, 0.08, 24).rotateX(Math.PI / 2).translate(0, 0, -0.04);
    this.body.add(new Mesh(box, bodyMaterial), new Mesh(lens, bodyMaterial));
    const quad = new PlaneGeometry(1, 1);
    const screen = new Mesh(quad, this.screenMaterial);
    setPickTag(this.plane, this.screenTag);
    this.plane.add(screen, this.grid, this.strata, this.selected);
    this.rig.add(this.body, this.frustum, this.plane, this.samples);
    this.owned.push(bodyMaterial, box, lens, quad, this.screenMaterial, this.frustum.geometry, this.frustum.material);
    this.owned.push(this.grid.geometry, this.grid.material, this.strata.geometry, this.strata.material);
    this.owned.push(this.selected.geometry, this.selected.material, this.samples.material, this.samples.material.map!);
  }

  /** Brings the drawing in line with the camera, the screen's size and the visualization options. */
  sync(state: CameraScreenState): void {
    const { camera } = state;
    const rays = new CameraRays(camera);
    this.rig.position.copy(rays.eye);
    cameraRigQuaternion(rays, this.rig.quaternion);
    const grid = screenGrid(camera);
    this.current = grid;
    const { columns, rows, distance, halfWidth, halfHeight } = grid;
    this.plane.position.set(0, 0, -distance);
    this.plane.scale.set(2 * halfWidth, 2 * halfHeight, 1);
    this.updateFrustum(grid);
    if (this.gridKey !== `${columns}×${rows}`) {
      this.gridKey = `${columns}×${rows}`;
      this.screenTag.columns = columns;
      this.screenTag.rows = rows;
      this.texture.dispose();
      this.texture = untracedTexture(columns, rows);
      this.screenMaterial.map = this.texture;
      this.screenMaterial.needsUpdate = true;
      replaceGeometry(this.grid, cellLines(columns, rows, 1));
    }
    // Overlays are children of the plane, whose z scale is 1: their z is in metres.
    this.grid.position.z = LIFT * distance;
    this.updateSelected(state.selectedPixel, grid);
    this.updateSamples(state, grid);
  }

  /** From the camera's eye: hides the body and frustum (they would fill the view) and lets the scene show through the screen. */
  setViewedFromEye(fromEye: boolean): void {
    this.body.visible = !fromEye;
    this.frustum.visible = !fromEye;
    this.screenMaterial.opacity = fromEye ? SCREEN_OPACITY_FROM_EYE : SCREEN_OPACITY;
  }

  /** Colours the cells with the traced pixels; ignored when it is for another screen size (a stale trace). */
  setScreenRays(rays: ScreenRays): void {
    const { columns, rows } = this.current;
    if (rays.columns !== columns || rays.rows !== rows) return;
    const data = this.texture.image.data as Uint8Array;
    for (const trace of rays.traces) {
      const [x, y] = trace.pixel;
      // Texture rows run bottom-up; the tracer's rows top-down.
      const offset = ((rows - 1 - y) * columns + x) * 4;
      // round(clamp(c)·255), no gamma: as the render window's quantize (toRgba8) does.
      for (let c = 0; c < 3; c++) data[offset + c] = Math.round(Math.min(1, Math.max(0, trace.color[c])) * 255);
    }
    this.texture.needsUpdate = true;
  }

  dispose(): void {
    this.texture.dispose();
    for (const item of this.owned) item.dispose();
    this.samples.geometry.dispose();
  }

  private updateFrustum({ distance, halfWidth, halfHeight }: ScreenGrid): void {
    const attribute = this.frustum.geometry.getAttribute('position') as Float32BufferAttribute;
    const corners = [
      [-halfWidth, halfHeight],
      [halfWidth, halfHeight],
      [halfWidth, -halfHeight],
      [-halfWidth, -halfHeight],
    ];
    corners.forEach(([x, y], i) => {
      attribute.setXYZ(2 * i, 0, 0, 0);
      attribute.setXYZ(2 * i + 1, x, y, -distance);
    });
    attribute.needsUpdate = true;
    this.frustum.geometry.computeBoundingSphere();
  }

  private updateSelected(pixel: [number, number] | null, { columns, rows, distance }: ScreenGrid): void {
    this.selected.visible = pixel !== null;
    if (!pixel) return;
    const [x, y] = pixel;
    this.selected.scale.set(1 / columns, 1 / rows, 1);
    this.selected.position.set(-0.5 + (x + 0.5) / columns, 0.5 - (y + 0.5) / rows, 2 * LIFT * distance);
  }

  /** The dots of every sub-pixel sample and the s×s cells they stratify (only remade when they change). */
  private updateSamples(state: CameraScreenState, grid: ScreenGrid): void {
    const s = state.settings.supersampling;
    const show = state.showSamplePoints;
    this.samples.visible = show;
    this.strata.visible = show && s > 1;
    if (!show) return;
    const { columns, rows, distance, halfHeight } = grid;
    const key = `${columns}×${rows}:${s}:${state.settings.samplePattern}:${distance}:${halfHeight}`;
    if (key === this.samplesKey) return;
    this.samplesKey = key;
    const count = columns * rows * s * s;
    const previous = this.samples.geometry.getAttribute('position');
    const positions = previous && previous.count === count ? (previous.array as Float32Array) : new Float32Array(count * 3);
    samplePoints(grid, s, state.settings.samplePattern, positions);
    if (previous && previous.array === positions) {
      previous.needsUpdate = true;
      this.samples.geometry.computeBoundingSphere();
    } else {
      replaceGeometry(this.samples, new BufferGeometry().setAttribute('position', new Float32BufferAttribute(positions, 3)));
    }
    this.samples.position.z = 3 * LIFT * distance;
    const cell = (2 * halfHeight) / rows;
    this.samples.material.size = Math.min(cell / s, cell / 3) * 0.55;
    replaceGeometry(this.strata, cellLines(columns * s, rows * s, s));
    this.strata.position.z = LIFT * distance;
  }
}

/** Swaps a drawable's geometry, freeing the old one's GPU buffers. */
function replaceGeometry(object: LineSegments | Points, geometry: BufferGeometry): void {
  object.geometry.dispose();
  object.geometry = geometry;
}

/**
 * Lines between the cells of a columns × rows grid on the unit square (−0.5..0.5), leaving
 * out every `skip`-th line (those the coarser pixel grid already draws; 1 draws them all).
 */
function cellLines(columns: number, rows: number, skip: number): BufferGeometry {
  const positions: number[] = [];
  for (let i = 0; i <= columns; i++) {
    if (skip > 1 && i % skip === 0) continue;
    const x = -0.5 + i / columns;
    positions.push(x, -0.5, 0, x, 0.5, 0);
  }
  for (let j = 0; j <= rows; j++) {
    if (skip > 1 && j % skip === 0) continue;
    const y = 0.5 - j / rows;
    positions.push(-0.5, y, 0, 0.5, y, 0);
  }
  return new BufferGeometry().setAttribute('position', new Float32BufferAttribute(positions, 3));
}

/** A square frame around the unit square's edge, `border` wide (a share of the side), as a mesh: WebGL lines are 1 px. */
function frameGeometry(border: number): BufferGeometry {
  const outer = new Shape().moveTo(-0.5, -0.5).lineTo(0.5, -0.5).lineTo(0.5, 0.5).lineTo(-0.5, 0.5).closePath();
  const inner = 0.5 - border;
  outer.holes.push(new Path().moveTo(-inner, -inner).lineTo(-inner, inner).lineTo(inner, inner).lineTo(inner, -inner).closePath());
  return new ShapeGeometry(outer);
}

function untracedTexture(columns: number, rows: number): DataTexture {
  const data = new Uint8Array(columns * rows * 4);
  for (let i = 0; i < columns * rows; i++) data.set([...UNTRACED, 255], i * 4);
  const texture = new DataTexture(data, columns, rows);
  texture.magFilter = NearestFilter;
  texture.minFilter = NearestFilter;
  texture.needsUpdate = true;
  return texture;
}

/** A round dot with a dark rim, so sample points read on light and dark pixels alike. */
function dotTexture(): DataTexture {
  const size = 32;
  const data = new Uint8Array(size * size * 4);
  for (let y = 0; y < size; y++) {
    for (let x = 0; x < size; x++) {
      const r = Math.hypot(x + 0.5 - size / 2, y + 0.5 - size / 2) / (size / 2);
      const value = r < 0.62 ? 255 : 20;
      data.set([value, value, value, r < 1 ? 255 : 0], (y * size + x) * 4);
    }
  }
  const texture = new DataTexture(data, size, size);
  texture.needsUpdate = true;
  return texture;
}
