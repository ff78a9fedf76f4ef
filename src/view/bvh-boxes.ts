import { type Box3, BufferGeometry, Color, Float32BufferAttribute, Group, LineBasicMaterial, LineDashedMaterial, LineSegments, type Matrix4 } from 'three';
import type { LabState } from '../lab-state/lab-state.ts';
import { loadMeshes } from '../render/load-meshes-browser.ts';
import type { MeshLibrary } from '../scene/mesh-data.ts';
import { meshNamesInScene } from '../scene/mesh-names.ts';
import { type BvhNode, bvhTree } from '../tracer/bvh-tree.ts';
import { meshAccel } from '../tracer/shapes/mesh-accel.ts';
import { buildTracerScene, objectToWorld } from '../tracer/tracer-scene.ts';
import { countPixelTests } from '../tracer/triangle-test-count.ts';
import type { MeshLoader } from './scene-sync.ts';

/** BVH boxes: solid orange lines; the level asked for at full strength, the boxes around them faint. */
const BVH_COLOR = [0.96, 0.45, 0.05] as const;
const PARENT_ALPHA = 0.22;
/** With a pixel selected, the tree steps back so that its ray's boxes stand out. */
const BEHIND_RAY_ALPHA = 0.12;
/**
 * The selected pixel's ray: boxes it entered solid bright green, boxes whose test failed
 * (their subtree skipped) dashed red, so the two differ by more than colour.
 */
const ENTERED_COLOR = [0.13, 0.9, 0.35] as const;
const MISSED_COLOR = 0xef2636;
/** Whole-object bounding boxes: dashed cyan, so that they differ from BVH boxes by more than colour. */
const BOUNDS_COLOR = 0x0891b2;
/** Drawn over the scene: the boxes inside a model would otherwise be hidden by it. */
const ON_TOP = 10;

// The 12 edges of a box as pairs of its 8 corners (corner bit 1: max x, 2: max y, 4: max z).
const EDGES = [0, 1, 2, 3, 4, 5, 6, 7, 0, 2, 1, 3, 4, 6, 5, 7, 0, 4, 1, 5, 2, 6, 3, 7];

/**
 * The acceleration structures the tracer uses, drawn as wireframe boxes in the 3D view:
 * the BVH of mesh objects (the selected mesh object's, or every mesh object's when none is
 * selected) down to `bvh.depth`, and, with `bvh.showBounds`, every object's world bounding
 * box, the one the tracer's slab test tries before the object itself. With a pixel selected,
 * the BVH boxes its primary ray tested stand out (src/tracer/triangle-test-count.ts walks
 * the tree as the tracer's cast does): entered ones solid green, failed ones dashed red, whatever the depth.
 *
 * Both come from the tracer's own code (buildTracerScene, meshAccel), so they are the real
 * boxes, not a look-alike. Models load asynchronously; `changed` is called when the boxes
 * were redrawn, so the owner can ask the view for a frame.
 */
export class BvhBoxes {
  /** Add this to the view's scene (LabView.setBvhLayer). */
  readonly object = new Group();
  private readonly bvhMaterial = new LineBasicMaterial({ vertexColors: true, transparent: true, depthTest: false, depthWrite: false });
  private readonly boundsMaterial = new LineDashedMaterial({ color: BOUNDS_COLOR, dashSize: 0.08, gapSize: 0.05, depthTest: false, depthWrite: false });
  private readonly enteredMaterial = new LineBasicMaterial({ color: new Color(...ENTERED_COLOR), depthTest: false, depthWrite: false });
  private readonly missedMaterial = new LineDashedMaterial({ color: MISSED_COLOR, dashSize: 0.02, gapSize: 0.015, depthTest: false, depthWrite: false });
  private shown: Pick<LabState, 'scene' | 'selection' | 'selectedPixel' | 'bvh'> | null = null;
  private request = 0;

  constructor(
    private readonly changed: () => void,
    private readonly loader: MeshLoader = loadMeshes,
    /** Told when a model cannot be loaded (the view reports it already; tests listen). */
    private readonly failed: (error: unknown) => void = () => {},
  ) {
    this.object.name = 'bvh-boxes';
  }

  /** Redraws the boxes when what they show changed: the scene, the selection, the selected pixel or the BVH options. */
  update(state: LabState): void {
    const shown = this.shown;
    if (shown && shown.scene === state.scene && shown.selection === state.selection && shown.selectedPixel === state.selectedPixel && shown.bvh === state.bvh)
      return;
    this.shown = { scene: state.scene, selection: state.selection, selectedPixel: state.selectedPixel, bvh: state.bvh };
    const request = ++this.request;
    if (!state.bvh.show && !state.bvh.showBounds) {
      this.draw(state, null);
      return;
    }
    this.loader(meshNamesInScene(state.scene)).then(
      (meshes) => {
        // A newer state may have asked for other boxes while the models loaded.
        if (request === this.request) this.draw(state, meshes);
      },
      (error: unknown) => this.failed(error),
    );
  }

  dispose(): void {
    this.clear();
    for (const material of [this.bvhMaterial, this.boundsMaterial, this.enteredMaterial, this.missedMaterial]) material.dispose();
  }

  private draw(state: LabState, meshes: MeshLibrary | null): void {
    this.clear();
    if (meshes) {
      if (state.bvh.show) for (const lines of [...this.bvhLines(state, meshes), ...this.rayLines(state, meshes)]) this.object.add(lines);
      if (state.bvh.showBounds) this.object.add(this.boundsLines(state, meshes));
    }
    this.changed();
  }

  /** The BVH boxes of the selected mesh object, or of every mesh object when no mesh object is selected. */
  private bvhLines(state: LabState, meshes: MeshLibrary): LineSegments[] {
    const meshObjects = state.scene.objects.filter((object) => object.shape === 'mesh' && object.mesh !== undefined && meshes.has(object.mesh));
    const selected = meshObjects.filter((object) => state.selection?.kind === 'object' && state.selection.id === object.id);
    const faint = state.selectedPixel ? BEHIND_RAY_ALPHA : 1;
    return (selected.length > 0 ? selected : meshObjects).map((object) => {
      const tree = bvhTree(meshAccel(meshes.get(object.mesh!)!).bvh);
      const lines = new LineSegments(treeGeometry(tree.root, state.bvh.depth, faint), this.bvhMaterial);
      placeAt(lines, objectToWorld(object));
      lines.name = `bvh:${object.id}`;
      return lines;
    });
  }

  /** The BVH boxes the selected pixel's primary ray tested, per model it reached: entered, and missed. */
  private rayLines(state: LabState, meshes: MeshLibrary): LineSegments[] {
    if (!state.selectedPixel) return [];
    const tests = countPixelTests(buildTracerScene(state.scene, meshes), meshes, state.selectedPixel);
    return tests.objects.flatMap(({ id, mesh }) => {
      const object = state.scene.objects.find((candidate) => candidate.id === id);
      if (!object || !mesh) return [];
      return (['entered', 'missed'] as const).flatMap((outcome) => {
        const nodes = mesh.visits.filter((visit) => visit.entered === (outcome === 'entered')).map((visit) => visit.node);
        if (nodes.length === 0) return [];
        const lines = new LineSegments(nodeGeometry(nodes), outcome === 'entered' ? this.enteredMaterial : this.missedMaterial);
        placeAt(lines, objectToWorld(object));
        if (outcome === 'missed') lines.computeLineDistances();
        lines.renderOrder = ON_TOP + 1;
        lines.name = `bvh-ray-${outcome}:${id}`;
        return [lines];
      });
    });
  }

  /** Every object's world bounding box, exactly as the tracer's shapes compute it. */
  private boundsLines(state: LabState, meshes: MeshLibrary): LineSegments {
    const boxes = buildTracerScene(state.scene, meshes).shapes.map((shape) => shape.worldBounds);
    const lines = new LineSegments(boxGeometry(boxes), this.boundsMaterial);
    lines.computeLineDistances();
    lines.renderOrder = ON_TOP;
    lines.name = 'bounds';
    return lines;
  }

  private clear(): void {
    for (const child of [...this.object.children]) {
      this.object.remove(child);
      if (child instanceof LineSegments) child.geometry.dispose();
    }
  }
}

function placeAt(lines: LineSegments, matrix: Matrix4): void {
  lines.matrixAutoUpdate = false;
  lines.matrix.copy(matrix);
  lines.renderOrder = ON_TOP;
}

/**
 * The boxes of the tree from the root down to `depth`: those at `depth` (and leaves above it)
 * at full strength, their ancestors faint, so the nesting shows without hiding the level asked for.
 */
function treeGeometry(root: BvhNode, depth: number, strength: number): BufferGeometry {
  const positions: number[] = [];
  const colors: number[] = [];
  const visit = (node: BvhNode) => {
    const last = node.depth >= depth || !node.left || !node.right;
    const b = node.bounds;
    pushBox(positions, b[0], b[1], b[2], b[3], b[4], b[5]);
    for (let i = 0; i < EDGES.length; i++) colors.push(...BVH_COLOR, (last ? 1 : PARENT_ALPHA) * strength);
    if (!last) {
      visit(node.left!);
      visit(node.right!);
    }
  };
  visit(root);
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new Float32BufferAttribute(positions, 3));
  geometry.setAttribute('color', new Float32BufferAttribute(colors, 4));
  return geometry;
}

/** The edges of BVH nodes' boxes, in the model's own space. */
function nodeGeometry(nodes: readonly BvhNode[]): BufferGeometry {
  const positions: number[] = [];
  for (const { bounds: b } of nodes) pushBox(positions, b[0], b[1], b[2], b[3], b[4], b[5]);
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new Float32BufferAttribute(positions, 3));
  return geometry;
}

function boxGeometry(boxes: Box3[]): BufferGeometry {
  const positions: number[] = [];
  for (const { min, max } of boxes) pushBox(positions, min.x, min.y, min.z, max.x, max.y, max.z);
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new Float32BufferAttribute(positions, 3));
  return geometry;
}

/** Appends the 12 edges of the box [x0, x1] × [y0, y1] × [z0, z1] as 24 line-segment points. */
function pushBox(out: number[], x0: number, y0: number, z0: number, x1: number, y1: number, z1: number): void {
  for (const corner of EDGES) out.push(corner & 1 ? x1 : x0, corner & 2 ? y1 : y0, corner & 4 ? z1 : z0);
}
