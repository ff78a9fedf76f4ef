import type { Vec3 } from '../../scene/scene.ts';
import { isGuideTarget } from '../../quest/lab-controls.ts';

/**
 * Where the hint ring goes for a guide target (docs/levels.md: "tracer.supersampling",
 * "view.item:ball", "screen.pixel:3,2"). The names are the levels' stable vocabulary
 * (quest/lab-controls.ts); each element that draws a control marks it with the name
 * (`data-guide`) and answers for it as a GuideHost, so the ring needs no knowledge of any
 * element's insides. A target with no element on the page (an object in the 3D view, or the
 * camera's screen while the flat preview is hidden) is ringed at its point in the 3D view.
 */

/** A box on the screen, in viewport CSS px. */
export interface ScreenBox {
  left: number;
  top: number;
  width: number;
  height: number;
}

/** What finding a target needs of the lab. */
export interface GuideStage {
  /** The elements on the page that carry a guide id. */
  elements(id: string): Element[];
  /** Where a world point is on the canvas (CSS px from its top-left), or null. */
  project(point: Vec3): { x: number; y: number } | null;
  canvas: HTMLElement | null;
  scene: { objects: readonly { id: string; position: Vec3 }[]; lights: readonly { id: string; position: Vec3 }[]; camera: { position: Vec3 } };
  /** On a small screen showing the tasks, the button that shows the panels instead (lab-compact.css.ts); else null. */
  panelsButton?: Element | null;
}

/** The centre of a scene item (object or light) by id, for `view.item:<id>`. */
export function itemPosition(scene: Pick<GuideStage['scene'], 'objects' | 'lights'>, id: string): Vec3 | undefined {
  return (scene.objects.find((o) => o.id === id) ?? scene.lights.find((l) => l.id === id))?.position;
}

/**
 * The point in the 3D view that stands for a target without an element: the item of
 * `view.item:<id>`, the camera for the camera's screen and its pixels; undefined otherwise.
 */
export function viewPointOf(target: string, scene: GuideStage['scene']): Vec3 | undefined {
  if (!isGuideTarget(target)) return undefined;
  if (target.startsWith('view.item:')) return itemPosition(scene, target.slice('view.item:'.length));
  if (target === 'screen.grid' || target.startsWith('screen.pixel:')) return scene.camera.position;
  return undefined;
}

/**
 * A control inside the closed render window is reached through the button that opens it:
 * while the window is hidden the ring goes there instead.
 */
const REACHED_THROUGH: Readonly<Record<string, string>> = {
  'render.start': 'render.open',
  'render.cancel': 'render.open',
  'render.save': 'render.open',
  'render.zoom': 'render.open',
  'render.compare': 'render.open',
  'render.close': 'render.open',
};

/** Size of the ring around a point in the 3D view. */
const POINT_RING_PX = 64;

/** The box to ring, in viewport px; null while the target is not on the page (or behind the eye). */
export function guideRect(target: string, stage: GuideStage): ScreenBox | null {
  const shown = elementBox(target, stage) ?? (REACHED_THROUGH[target] ? elementBox(REACHED_THROUGH[target], stage) : null) ?? panelsButtonBox(target, stage);
  if (shown) return shown;
  const point = viewPointOf(target, stage.scene);
  const projected = point && stage.project(point);
  const canvas = stage.canvas?.getBoundingClientRect();
  if (!projected || !canvas) return null;
  return {
    left: canvas.left + projected.x - POINT_RING_PX / 2,
    top: canvas.top + projected.y - POINT_RING_PX / 2,
    width: POINT_RING_PX,
    height: POINT_RING_PX,
  };
}

/**
 * A control of the panels while a small screen's column shows the tasks: it is on the page but
 * takes no room, and is reached through the button that shows the panels.
 */
function panelsButtonBox(target: string, stage: GuideStage): ScreenBox | null {
  const button = stage.panelsButton?.getBoundingClientRect();
  if (!button || button.width === 0 || stage.elements(target).length === 0) return null;
  return { left: button.left, top: button.top, width: button.width, height: button.height };
}

/** The box around every element on the page that carries `id` and takes room; null when none does. */
function elementBox(id: string, stage: GuideStage): ScreenBox | null {
  const boxes = stage
    .elements(id)
    .map((element) => element.getBoundingClientRect())
    .filter((box) => box.width > 0 && box.height > 0);
  if (boxes.length > 0) {
    const left = Math.min(...boxes.map((box) => box.left));
    const top = Math.min(...boxes.map((box) => box.top));
    return { left, top, width: Math.max(...boxes.map((box) => box.right)) - left, height: Math.max(...boxes.map((box) => box.bottom)) - top };
  }
  return null;
}
