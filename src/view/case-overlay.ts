import {
  BoxGeometry,
  ConeGeometry,
  CylinderGeometry,
  type BufferGeometry,
  EdgesGeometry,
  Group,
  LineBasicMaterial,
  LineSegments,
  type Material,
  Mesh,
  MeshBasicMaterial,
  OctahedronGeometry,
  SphereGeometry,
  Vector3,
} from 'three';
import { CASE_MARK_COLORS, caseDrawingExtent, type CaseDrawing, type CaseShape, type SegmentMark } from '../quest/code-labs/case-drawing.ts';
import type { Store } from '../lab-state/store.ts';
import type { Vec3 } from '../scene/scene.ts';
import { paletteNameFor, rayPalette } from './ray-palette.ts';

/** Parts of the case's size (the largest distance between its points): thick enough to see, thin enough not to hide the points. */
const RAY_RADIUS = 0.008;
const ARROW_LENGTH = 0.05;
const POINT_RADIUS = 0.03;
const CLOUD_POINT_RADIUS = 0.01;
/** The case's objects: a light skin and dark lines, apart from the scene's own objects. */
const SHAPE_COLOR = 0xdde3ea;
const SHAPE_LINE_COLOR = 0x3b4450;

const up = new Vector3(0, 1, 0);

/**
 * A code lab's failing case in the 3D view (quest/code-labs/case-drawing.ts): the rays as
 * cylinders with an arrowhead, as the ray tree's rays are drawn, in the ray legend's colour
 * for a camera ray (`primary`); the shapes as see-through outlines; the expected and got
 * points in their own colours and shapes. Sized from the case's extent, since a random case
 * may lie anywhere in a 10 m box and be 0.2 m or 10 m across.
 */
export class CaseOverlay {
  readonly group = new Group();
  private drawing: CaseDrawing | null = null;
  private readonly owned: (BufferGeometry | Material)[] = [];

  constructor(
    private readonly view: {
      /** Glides the view to where these points fit. */
      frame(points: readonly Vec3[]): void;
      /** Something drawn changed: a frame is due. */
      drawn(): void;
      /** The ray options' palette is read when a case is drawn. */
      store: Pick<Store, 'state'>;
    },
  ) {
    this.group.name = 'code-lab-case';
    this.group.visible = false;
  }

  /** The case shown now, or null. */
  get shown(): CaseDrawing | null {
    return this.drawing;
  }

  /** The world points a view must fit to show the case (none when nothing is shown). */
  get extent(): Vec3[] {
    return this.drawing ? caseDrawingExtent(this.drawing).map((p) => [p.x, p.y, p.z]) : [];
  }

  /** Draws `drawing` (replacing the case before) and frames it; null clears. */
  show(drawing: CaseDrawing | null): void {
    this.draw(drawing);
    if (drawing) this.view.frame(this.extent);
    this.view.drawn();
  }

  dispose(): void {
    this.clear();
  }

  private draw(drawing: CaseDrawing | null): void {
    this.clear();
    this.drawing = drawing;
    this.group.visible = drawing !== null;
    if (!drawing) return;
    // The case's rays in the legend's colour for a camera ray, in the palette the ray options choose.
    const rayColor = rayPalette(paletteNameFor(this.view.store.state.rays.colorBlindPalette)).primary;
    const size = caseSize(drawing);
    // The normal belongs to the surface: in the outlines' colour, not in one of the answers'.
    const colorOf = (mark: SegmentMark) => (mark === 'ray' ? rayColor : mark === 'normal' ? SHAPE_LINE_COLOR : CASE_MARK_COLORS[mark]);
    for (const segment of drawing.segments) {
      const from = new Vector3(segment.from.x, segment.from.y, segment.from.z);
      const to = new Vector3(segment.to.x, segment.to.y, segment.to.z);
      // Drawn over the scene, as the points are: a mirror case's reflected ray may point into the floor, a refraction's into the glass.
      const material = this.own(new MeshBasicMaterial({ color: colorOf(segment.mark), depthTest: false, transparent: true }));
      const length = from.distanceTo(to);
      if (length === 0) continue;
      const direction = to.clone().sub(from).divideScalar(length);
      const arrow = segment.arrow ? Math.min(size * ARROW_LENGTH, length / 2) : 0;
      const body = new Mesh(this.own(new CylinderGeometry(size * RAY_RADIUS, size * RAY_RADIUS, length - arrow, 8)), material);
      body.position.copy(from).addScaledVector(direction, (length - arrow) / 2);
      body.quaternion.setFromUnitVectors(up, direction);
      body.renderOrder = 9;
      this.group.add(body);
      if (arrow > 0) {
        const head = new Mesh(this.own(new ConeGeometry(arrow / 2.5, arrow, 12)), material);
        head.position.copy(to).addScaledVector(direction, -arrow / 2);
        head.quaternion.setFromUnitVectors(up, direction);
        head.renderOrder = 9;
        this.group.add(head);
      }
    }
    for (const shape of drawing.shapes) {
      // A faint skin and darker lines: seen against the floor and the scene's own objects alike.
      const { geometry, center } = shapeGeometry(shape);
      const skin = new Mesh(this.own(geometry), this.own(new MeshBasicMaterial({ color: SHAPE_COLOR, transparent: true, opacity: 0.18, depthWrite: false })));
      const outline = new LineSegments(this.own(new EdgesGeometry(geometry, 1)), this.own(new LineBasicMaterial({ color: SHAPE_LINE_COLOR })));
      skin.position.set(center.x, center.y, center.z);
      outline.position.copy(skin.position);
      this.group.add(skin, outline);
    }
    const radius = size * (drawing.cloud ? CLOUD_POINT_RADIUS : POINT_RADIUS);
    for (const point of drawing.points) {
      const geometry = point.mark === 'expected' ? new SphereGeometry(radius, 16, 8) : new OctahedronGeometry(radius * 1.4);
      // Drawn over everything, last (the transparent pass, after the rays): a hit on the far side of the sphere or behind an object still shows.
      const material = this.own(new MeshBasicMaterial({ color: CASE_MARK_COLORS[point.mark], depthTest: false, transparent: true }));
      const mesh = new Mesh(this.own(geometry), material);
      mesh.position.set(point.at.x, point.at.y, point.at.z);
      mesh.renderOrder = 10;
      this.group.add(mesh);
    }
  }

  private clear(): void {
    this.group.clear();
    for (const thing of this.owned.splice(0)) thing.dispose();
    this.drawing = null;
  }

  private own<T extends BufferGeometry | Material>(thing: T): T {
    this.owned.push(thing);
    return thing;
  }
}

/** The largest distance between the case's points: what the rays' thickness and the points' size follow. */
function caseSize(drawing: CaseDrawing): number {
  const points = caseDrawingExtent(drawing);
  let size = 0;
  for (const a of points) for (const b of points) size = Math.max(size, Math.hypot(a.x - b.x, a.y - b.y, a.z - b.z));
  return size || 1;
}

/** A shape's geometry around its centre: a sphere's latitude and longitude lines, a box's twelve edges. */
function shapeGeometry(shape: CaseShape): { geometry: BufferGeometry; center: { x: number; y: number; z: number } } {
  if (shape.kind === 'sphere') return { geometry: new SphereGeometry(shape.radius, 24, 12), center: shape.center };
  const { min, max } = shape;
  return {
    geometry: new BoxGeometry(max.x - min.x, max.y - min.y, max.z - min.z),
    center: { x: (min.x + max.x) / 2, y: (min.y + max.y) / 2, z: (min.z + max.z) / 2 },
  };
}
