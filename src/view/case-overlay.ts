import {
  BoxGeometry,
  BufferGeometry,
  CanvasTexture,
  ConeGeometry,
  DoubleSide,
  CylinderGeometry,
  EdgesGeometry,
  Group,
  LineBasicMaterial,
  LineSegments,
  type Material,
  Mesh,
  MeshBasicMaterial,
  OctahedronGeometry,
  SphereGeometry,
  Sprite,
  SpriteMaterial,
  Vector3,
} from 'three';
import {
  CASE_MARK_COLORS,
  CELL_FILL_COLORS,
  caseDrawingExtent,
  SHADING_VECTOR_COLORS,
  type CaseDrawing,
  type CasePoint,
  type CaseShape,
  type QuadFill,
  type SegmentMark,
} from '../quest/code-labs/case-drawing.ts';
import type { Store } from '../lab-state/store.ts';
import type { Vec3 } from '../scene/scene.ts';
import { paletteNameFor, rayPalette } from './ray-palette.ts';

/** Parts of the case's size (the largest distance between its points): thick enough to see, thin enough not to hide the points. */
const RAY_RADIUS = 0.008;
const ARROW_LENGTH = 0.05;
const POINT_RADIUS = 0.03;
const CLOUD_POINT_RADIUS = 0.01;
/** A pixel's grid lines and its samples: finer than the rays and the answers, as there are up to 64 of them. */
const GRID_RADIUS = 0.003;
const SAMPLE_RADIUS = 0.016;
/** A vector's letter: its height, and how far beyond the arrow's tip it stands. */
const LABEL_SIZE = 0.07;
const LABEL_GAP = 0.04;
/** The case's objects: a light skin and dark lines, apart from the scene's own objects. */
const SHAPE_COLOR = 0xdde3ea;
const SHAPE_LINE_COLOR = 0x3b4450;
/** How see-through each kind of quad's skin is: the pixel hides the scene behind its samples; a cell's fill lets the grid show. */
const QUAD_OPACITY: Readonly<Record<QuadFill, number>> = { surface: 0.45, pixel: 1, empty: 0.6, crowded: 0.6 };
/** A piece of the shaded surface: a blue-grey, darker than the outlines' skin, so that it reads against a light floor. */
const SURFACE_COLOR = 0x8fa3b8;

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
  private readonly owned: (BufferGeometry | Material | CanvasTexture)[] = [];

  constructor(
    private readonly view: {
      /** Glides the view to where these points fit, looking from `direction` (from the points toward the eye) when given. */
      frame(points: readonly Vec3[], direction?: Vec3): void;
      /** A case was drawn (`shown`) or cleared: a frame is due, and the scene's own rays stand aside while a case is shown. */
      drawn(shown: boolean): void;
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
    const from = drawing?.lookFrom;
    if (drawing) this.view.frame(this.extent, from && [from.x, from.y, from.z]);
    this.view.drawn(drawing !== null);
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
    // The normal and the pixel's grid belong to the surface: in the outlines' colour, not in one of the answers'.
    const colorOf = (mark: SegmentMark) => {
      if (mark === 'ray') return rayColor;
      if (mark === 'normal' || mark === 'grid') return SHAPE_LINE_COLOR;
      return mark === 'expected' || mark === 'got' ? CASE_MARK_COLORS[mark] : SHADING_VECTOR_COLORS[mark];
    };
    for (const segment of drawing.segments) {
      const from = new Vector3(segment.from.x, segment.from.y, segment.from.z);
      const to = new Vector3(segment.to.x, segment.to.y, segment.to.z);
      // Drawn over the scene, as the points are: a mirror case's reflected ray may point into the floor, a refraction's into the glass.
      const material = this.own(new MeshBasicMaterial({ color: colorOf(segment.mark), depthTest: false, transparent: true }));
      const length = from.distanceTo(to);
      if (length === 0) continue;
      const direction = to.clone().sub(from).divideScalar(length);
      const arrow = segment.arrow ? Math.min(size * ARROW_LENGTH, length / 2) : 0;
      const radius = size * (segment.mark === 'grid' ? GRID_RADIUS : RAY_RADIUS);
      const body = new Mesh(this.own(new CylinderGeometry(radius, radius, length - arrow, 8)), material);
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
      if (segment.label) this.group.add(this.label(segment.label, colorOf(segment.mark), to.clone().addScaledVector(direction, size * LABEL_GAP), size));
    }
    for (const shape of drawing.shapes) {
      if (shape.kind === 'quad') {
        this.drawQuad(shape);
        continue;
      }
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
      const geometry =
        point.mark === 'got' ? new OctahedronGeometry(radius * 1.4) : new SphereGeometry(point.mark === 'sample' ? size * SAMPLE_RADIUS : radius, 16, 8);
      // Drawn over everything, last (the transparent pass, after the rays): a hit on the far side of the sphere or behind an object still shows.
      const material = this.own(new MeshBasicMaterial({ color: pointColor(point.mark), depthTest: false, transparent: true }));
      const mesh = new Mesh(this.own(geometry), material);
      mesh.position.set(point.at.x, point.at.y, point.at.z);
      mesh.renderOrder = 10;
      this.group.add(mesh);
    }
  }

  /**
   * A flat quad: its skin (over the scene, under the rays and points, so that a pixel hides
   * what is behind it and its cells' fills lie on it) and, for the surface and the pixel, its
   * outline.
   */
  private drawQuad(shape: Extract<CaseShape, { kind: 'quad' }>): void {
    const [a, b, c, d] = shape.corners;
    const geometry = this.own(new BufferGeometry().setFromPoints([a, b, c, a, c, d].map((p) => new Vector3(p.x, p.y, p.z))));
    const color = shape.fill === 'empty' || shape.fill === 'crowded' ? CELL_FILL_COLORS[shape.fill] : shape.fill === 'pixel' ? 0xffffff : SURFACE_COLOR;
    const opacity = QUAD_OPACITY[shape.fill];
    const material = this.own(new MeshBasicMaterial({ color, transparent: true, opacity, depthTest: false, depthWrite: false, side: DoubleSide }));
    const skin = new Mesh(geometry, material);
    skin.renderOrder = shape.fill === 'pixel' ? 7 : 8;
    this.group.add(skin);
    if (shape.fill !== 'surface' && shape.fill !== 'pixel') return;
    const edges = [a, b, b, c, c, d, d, a].map((p) => new Vector3(p.x, p.y, p.z));
    const outline = new LineSegments(
      this.own(new BufferGeometry().setFromPoints(edges)),
      this.own(new LineBasicMaterial({ color: SHAPE_LINE_COLOR, depthTest: false })),
    );
    outline.renderOrder = 8;
    this.group.add(outline);
  }

  /** A vector's letter at `at`, facing the eye, in the vector's colour on a light halo so that it reads on any background. */
  private label(text: string, color: string | number, at: Vector3, size: number): Sprite {
    const canvas = document.createElement('canvas');
    canvas.width = canvas.height = 64;
    const context = canvas.getContext('2d');
    if (context) {
      context.font = 'bold 48px sans-serif';
      context.textAlign = 'center';
      context.textBaseline = 'middle';
      context.lineWidth = 8;
      context.strokeStyle = 'white';
      context.strokeText(text, 32, 34);
      context.fillStyle = typeof color === 'number' ? `#${color.toString(16).padStart(6, '0')}` : color;
      context.fillText(text, 32, 34);
    }
    const texture = this.own(new CanvasTexture(canvas));
    const sprite = new Sprite(this.own(new SpriteMaterial({ map: texture, depthTest: false, transparent: true })));
    sprite.position.copy(at);
    sprite.scale.setScalar(size * LABEL_SIZE);
    sprite.renderOrder = 11;
    return sprite;
  }

  private clear(): void {
    this.group.clear();
    for (const thing of this.owned.splice(0)) thing.dispose();
    this.drawing = null;
  }

  private own<T extends BufferGeometry | Material | CanvasTexture>(thing: T): T {
    this.owned.push(thing);
    return thing;
  }
}

/** A point's colour: the answers' own, the light's as its vector's, the shading point and the samples in the outlines' colour. */
function pointColor(mark: CasePoint['mark']): string | number {
  if (mark === 'expected' || mark === 'got') return CASE_MARK_COLORS[mark];
  return mark === 'light' ? SHADING_VECTOR_COLORS.light : SHAPE_LINE_COLOR;
}

/** The largest distance between the case's points: what the rays' thickness and the points' size follow. */
function caseSize(drawing: CaseDrawing): number {
  const points = caseDrawingExtent(drawing);
  let size = 0;
  for (const a of points) for (const b of points) size = Math.max(size, Math.hypot(a.x - b.x, a.y - b.y, a.z - b.z));
  return size || 1;
}

/** A shape's geometry around its centre: a sphere's latitude and longitude lines, a box's twelve edges. */
function shapeGeometry(shape: Exclude<CaseShape, { kind: 'quad' }>): { geometry: BufferGeometry; center: { x: number; y: number; z: number } } {
  if (shape.kind === 'sphere') return { geometry: new SphereGeometry(shape.radius, 24, 12), center: shape.center };
  const { min, max } = shape;
  return {
    geometry: new BoxGeometry(max.x - min.x, max.y - min.y, max.z - min.z),
    center: { x: (min.x + max.x) / 2, y: (min.y + max.y) / 2, z: (min.z + max.z) / 2 },
  };
}
