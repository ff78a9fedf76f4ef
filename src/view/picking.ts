import { type Intersection, type Object3D, Raycaster, Vector2, type Camera } from 'three';
import { cellAtUv } from './screen-grid.ts';

/** What a drawn part stands for, stored on it for picking. */
export type PickTag = { kind: 'object'; id: string } | { kind: 'light'; id: string } | { kind: 'camera' } | { kind: 'screen'; columns: number; rows: number };

/** What a click landed on. */
export type PickResult = { kind: 'object'; id: string } | { kind: 'light'; id: string } | { kind: 'camera' } | { kind: 'pixel'; pixel: [number, number] };

const PICK_KEY = 'rtPick';

/** Marks a drawn part (and so everything below it) as standing for `tag`. */
export function setPickTag(object: Object3D, tag: PickTag): void {
  object.userData[PICK_KEY] = tag;
}

function pickTagOf(object: Object3D): PickTag | null {
  // The nearest tagged ancestor: a light's bulb, cone and outline all pick the light.
  for (let node: Object3D | null = object; node; node = node.parent) {
    const tag = node.userData[PICK_KEY] as PickTag | undefined;
    if (tag) return tag;
  }
  return null;
}

/** Whether the part and all its ancestors are shown (three.js's raycaster tests hidden parts too). */
function shown(object: Object3D): boolean {
  for (let node: Object3D | null = object; node; node = node.parent) {
    if (!node.visible) return false;
  }
  return true;
}

/**
 * Turns pointer positions into rays and rays into what they hit: the nearest shown part
 * with a pick tag, so that lines (a frustum, a grid) and the ray layer never steal a click.
 */
export class Picker {
  readonly raycaster = new Raycaster();
  private readonly ndc = new Vector2();
  private readonly hits: Intersection[] = [];

  constructor() {
    // three.js counts a line as hit within 1 world unit by default: a frustum line would
    // then win every click near the camera. A couple of centimetres is a fair "on the line".
    this.raycaster.params.Line.threshold = 0.02;
    this.raycaster.params.Points.threshold = 0.02;
  }

  /** Aims the raycaster from `camera` through the pointer at (clientX, clientY) over `element`. */
  aim(camera: Camera, element: Element, clientX: number, clientY: number): Raycaster {
    const rect = element.getBoundingClientRect();
    this.ndc.set(((clientX - rect.left) / rect.width) * 2 - 1, -((clientY - rect.top) / rect.height) * 2 + 1);
    this.raycaster.setFromCamera(this.ndc, camera);
    return this.raycaster;
  }

  /** The nearest tagged, shown part among `roots` along the aimed ray, or null for empty space. */
  pick(roots: Object3D[]): PickResult | null {
    this.hits.length = 0;
    this.raycaster.intersectObjects(roots, true, this.hits);
    for (const hit of this.hits) {
      if (!shown(hit.object)) continue;
      const tag = pickTagOf(hit.object);
      if (!tag) continue;
      if (tag.kind !== 'screen') return tag;
      const cell = hit.uv ? cellAtUv(hit.uv.x, hit.uv.y, tag.columns, tag.rows) : null;
      if (cell) return { kind: 'pixel', pixel: cell };
    }
    return null;
  }
}
