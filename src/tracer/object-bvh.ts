import type { Box3 } from 'three';
import type { Hit } from './hit.ts';
import type { Intersectable } from './intersectable.ts';
import type { Ray } from './ray.ts';
import { rayMeetsBox } from './ray-box.ts';
import type { RayCone } from './ray-cone.ts';
import { WalkStarts } from './walk-starts.ts';

/** Objects per leaf: past two, testing a leaf's objects costs more than one more level of boxes. */
const LEAF_SIZE = 2;
/**
 * A scene of up to this many objects is one leaf: a ray tests each object's box in the
 * scene's order, which was measured faster than walking a tree for the few objects of a lesson.
 */
const ONE_LEAF_UP_TO = 12;

/**
 * The objects of `bvhs` (in their order) whose box overlaps `box` and is not wholly outside
 * `cone` (when given), written into `out`: how many, or -1 when there are more than `limit`
 * (the shadow candidates of a hit or a patch of hits; more are not worth listing).
 */
export function listOverlapping(
  bvhs: readonly ObjectBvh[],
  box: Box3,
  out: Intersectable[],
  limit: number,
  cone: RayCone | null,
  from: Intersectable | null = null,
): number {
  let count = 0;
  for (const bvh of bvhs) {
    count = bvh.overlapping(box, out, count, limit, cone, from);
    if (count > limit) return -1;
  }
  return count;
}

/**
 * A top-level BVH over a scene's objects (their world bounding boxes), so that a ray tests
 * the objects near its path, not every object: the cost of a ray grows with the log of the
 * object count instead of the count (up to the scene limit of 256 objects). Built by median
 * splits along the widest axis of the objects' centres, nodes stored depth first (a node's
 * left child follows it), boxes in one Float64Array.
 */
export class ObjectBvh {
  /** min x, y, z, max x, y, z per node. */
  private readonly boxes: Float64Array;
  /** Inner node: its right child. Leaf: its first object in `items`. */
  private readonly link: Int32Array;
  /** Leaf: how many objects (≥ 1). Inner node: 0. */
  private readonly count: Int32Array;
  /** Inner node: the split axis, so rays visit the nearer child first. */
  private readonly axis: Uint8Array;
  private readonly items: Intersectable[] = [];
  /** The items' world boxes, 6 numbers each in the same order, for the overlap tests. */
  private readonly itemBoxes: Float64Array;
  /** Nodes still to visit: a walk from the root holds at most one per level, one from an object's leaf twice that. */
  private readonly stack: Int32Array;
  private readonly starts: WalkStarts;
  /**
   * The tree is one leaf (up to ONE_LEAF_UP_TO objects): the ray walks do not test its box.
   * It holds every object's box, so it only spares the objects' tests to a ray that misses
   * the whole scene, and in a closed room such as the Cornell box no ray does: there it cost
   * one slab test more per ray, of eight.
   */
  private readonly rootIsLeaf: boolean;

  constructor(objects: readonly Intersectable[]) {
    const nodes = Math.max(1, 2 * objects.length - 1);
    this.boxes = new Float64Array(nodes * 6);
    this.link = new Int32Array(nodes);
    this.count = new Int32Array(nodes);
    this.axis = new Uint8Array(nodes);
    this.stack = new Int32Array(nodes + 1);
    this.itemBoxes = new Float64Array(objects.length * 6);
    let used = 0;
    const leafSize = objects.length <= ONE_LEAF_UP_TO ? ONE_LEAF_UP_TO : LEAF_SIZE;
    const build = (group: Intersectable[]): number => {
      const node = used++;
      const box = this.boxes;
      box.fill(Infinity, node * 6, node * 6 + 3).fill(-Infinity, node * 6 + 3, node * 6 + 6);
      for (const { worldBounds: b } of group) {
        const mins = [b.min.x, b.min.y, b.min.z];
        const maxs = [b.max.x, b.max.y, b.max.z];
        for (let k = 0; k < 3; k++) {
          box[node * 6 + k] = Math.min(box[node * 6 + k], mins[k]);
          box[node * 6 + 3 + k] = Math.max(box[node * 6 + 3 + k], maxs[k]);
        }
      }
      if (group.length <= leafSize) {
        this.link[node] = this.items.length;
        this.count[node] = group.length;
        this.items.push(...group);
        return node;
      }
      const axis = widestCentreAxis(group);
      const centre = (o: Intersectable) => centreOf(o, axis);
      // Ties keep the scene's order (Array.prototype.sort is stable).
      const sorted = [...group].sort((a, b) => centre(a) - centre(b));
      const half = sorted.length >> 1;
      this.axis[node] = axis;
      build(sorted.slice(0, half));
      this.link[node] = build(sorted.slice(half));
      return node;
    };
    if (objects.length > 0) build([...objects]);
    this.items.forEach(({ worldBounds: { min, max } }, i) => this.itemBoxes.set([min.x, min.y, min.z, max.x, max.y, max.z], i * 6));
    this.starts = new WalkStarts(this.link, this.count, this.items);
    this.rootIsLeaf = this.count[0] > 0;
  }

  /** Its objects, in the order of its leaves. */
  objectsInOrder(): readonly Intersectable[] {
    return this.items;
  }

  /**
   * Writes the objects whose box overlaps `box` (and is not wholly outside `cone`, when
   * given) into `out` from `start` on, and returns the new end; stops early once it is past
   * `limit`. `from`: an object the box holds a point of, where the walk starts (walk-starts.ts).
   */
  overlapping(box: Box3, out: Intersectable[], start: number, limit: number, cone: RayCone | null = null, from: Intersectable | null = null): number {
    const { boxes, link, count, items, itemBoxes, stack } = this;
    if (items.length === 0) return start;
    setWithin(box);
    let end = start;
    let size = this.starts.fill(stack, from);
    while (size > 0 && end <= limit) {
      const node = stack[--size];
      if (!overlapsWithin(boxes, node * 6) || cone?.excludes(boxes, node * 6)) continue;
      const n = count[node];
      if (n > 0) {
        for (let i = link[node], last = i + n; i < last; i++) {
          if (overlapsWithin(itemBoxes, i * 6) && !cone?.excludes(itemBoxes, i * 6)) out[end++] = items[i];
        }
        continue;
      }
      stack[size++] = link[node];
      stack[size++] = node + 1;
    }
    return end;
  }

  /**
   * The nearest hit along the ray closer than hit.t, as testing every object would find it
   * (each object's own test keeps only hits nearer than hit.t). `skip` is not tested, nor,
   * when `within` is given, the objects whose box does not overlap it. `from`: the object the
   * ray starts on, where the walk starts (walk-starts.ts); of two objects hit at exactly the
   * same distance, the one found first is kept, so the walk's start decides such a tie.
   */
  nearest(ray: Ray, hit: Hit, skip: Intersectable | null, within: Box3 | null = null, from: Intersectable | null = null): void {
    const { boxes, link, count, axis, items, itemBoxes, stack } = this;
    if (items.length === 0) return;
    if (within) setWithin(within);
    const direction = ray.direction;
    let size = this.starts.fill(stack, from);
    while (size > 0) {
      const node = stack[--size];
      // Tested when taken, against the nearest hit so far: farther boxes are skipped.
      if ((node !== 0 || !this.rootIsLeaf) && !rayMeetsBox(ray, boxes, node * 6, hit.t)) continue;
      const n = count[node];
      if (n > 0) {
        for (let i = link[node], end = i + n; i < end; i++) {
          const item = items[i];
          if (item !== skip && (!within || overlapsWithin(itemBoxes, i * 6))) item.intersect(ray, hit);
        }
        continue;
      }
      // The child on the side the ray comes from is taken first (pushed last): the right
      // child holds the larger centres on the split axis, so a ray going toward −axis
      // meets it first. Its hit then skips the farther boxes.
      const left = node + 1;
      const right = link[node];
      const backward = (axis[node] === 0 ? direction.x : axis[node] === 1 ? direction.y : direction.z) < 0;
      stack[size++] = backward ? left : right;
      stack[size++] = backward ? right : left;
    }
  }

  /**
   * The objects whose box is not wholly outside `cone`, into `out` and their boxes into
   * `outBoxes` (how many; -1 past `limit`), in the order `nearest` tests them for a ray
   * whose direction has the signs `backwardAxes` (bit k set: negative along axis k): testing
   * them in that order finds exactly the hit `nearest` finds for every such ray inside the
   * cone (primary-candidates.ts says why).
   */
  itemsInCone(cone: RayCone, backwardAxes: number, out: Intersectable[], outBoxes: Float64Array, limit: number): number {
    const { boxes, link, count, axis, items, itemBoxes, stack } = this;
    if (items.length === 0) return 0;
    let end = 0;
    let size = 0;
    stack[size++] = 0;
    while (size > 0) {
      const node = stack[--size];
      if (cone.excludes(boxes, node * 6)) continue;
      const n = count[node];
      if (n > 0) {
        for (let i = link[node], last = i + n; i < last; i++) {
          if (cone.excludes(itemBoxes, i * 6)) continue;
          if (end === limit) return -1;
          for (let k = 0; k < 6; k++) outBoxes[end * 6 + k] = itemBoxes[i * 6 + k];
          out[end++] = items[i];
        }
        continue;
      }
      const left = node + 1;
      const right = link[node];
      const backward = (backwardAxes >> axis[node]) & 1;
      stack[size++] = backward ? left : right;
      stack[size++] = backward ? right : left;
    }
    return end;
  }

  /**
   * The first object found that the ray hits closer than ray.far (any-hit, for shadow rays),
   * or null. `skip` is not tested, nor, when `within` is given, the objects whose box does
   * not overlap it. `from`: the object the ray starts on, where the walk starts (walk-starts.ts).
   */
  firstBlocker(ray: Ray, skip: Intersectable | null, within: Box3 | null, from: Intersectable | null = null): Intersectable | null {
    const tMax = ray.far;
    const { boxes, link, count, items, itemBoxes, stack } = this;
    if (items.length === 0) return null;
    if (within) setWithin(within);
    let size = this.starts.fill(stack, from);
    while (size > 0) {
      const node = stack[--size];
      if ((node !== 0 || !this.rootIsLeaf) && !rayMeetsBox(ray, boxes, node * 6, tMax)) continue;
      const n = count[node];
      if (n > 0) {
        for (let i = link[node], end = i + n; i < end; i++) {
          const item = items[i];
          if (item !== skip && (!within || overlapsWithin(itemBoxes, i * 6)) && item.occludes(ray)) return item;
        }
        continue;
      }
      stack[size++] = link[node];
      stack[size++] = node + 1;
    }
    return null;
  }
}

/**
 * The box of the current query (set by setWithin): min x, y, z, max x, y, z. A typed array,
 * not module-level variables, as it is set for every hit and light: docs/performance.md,
 * "Numbers passed to calls".
 */
const within = new Float64Array(6);

function setWithin({ min, max }: Box3): void {
  within[0] = min.x;
  within[1] = min.y;
  within[2] = min.z;
  within[3] = max.x;
  within[4] = max.y;
  within[5] = max.z;
}

/** Box3.intersectsBox between the query box and boxes[at..at+5]. */
function overlapsWithin(boxes: Float64Array, at: number): boolean {
  const w = within;
  return w[3] >= boxes[at] && w[0] <= boxes[at + 3] && w[4] >= boxes[at + 1] && w[1] <= boxes[at + 4] && w[5] >= boxes[at + 2] && w[2] <= boxes[at + 5];
}

function centreOf(object: Intersectable, axis: number): number {
  const { min, max } = object.worldBounds;
  return axis === 0 ? min.x + max.x : axis === 1 ? min.y + max.y : min.z + max.z;
}

function widestCentreAxis(group: readonly Intersectable[]): number {
  let widest = 0;
  let widestSpread = -1;
  for (let axis = 0; axis < 3; axis++) {
    const centres = group.map((o) => centreOf(o, axis));
    const spread = Math.max(...centres) - Math.min(...centres);
    if (spread > widestSpread) {
      widest = axis;
      widestSpread = spread;
    }
  }
  return widest;
}
