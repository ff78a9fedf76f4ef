import type { Vec3 } from '../scene/scene.ts';
import { isGuideTarget, type ControlTarget, type LabPanel } from '../quest/lab-controls.ts';

/**
 * Where a guide target (docs/levels.md: "tracer.supersampling", "view.item:ball",
 * "screen.pixel:3,2") is on the page. The names are the levels' stable vocabulary; this
 * table ties each one to the element that carries it today, so a control can be restyled
 * or moved without touching a level file.
 *
 * A path is a list of CSS selectors: the first is looked up in the lab's shadow root, each
 * next one inside the shadow root (or, failing that, the light DOM) of the element before;
 * the last may match several elements (both pixel sliders), and the ring goes around all.
 */
export type ElementPath = readonly string[];

/** Where a target is: an element, a thing in the 3D view, or a pixel of the camera's screen. */
export type GuideLocation =
  | { kind: 'element'; path: ElementPath }
  | { kind: 'view-item'; id: string }
  /** The camera's screen: the flat preview when it is on the page, else the camera in the 3D view. */
  | { kind: 'camera-screen' }
  | { kind: 'pixel'; column: number; row: number };

const TOOLBAR = ['rt-scene-view', 'rt-view-toolbar'];
const group = (command: string) => `.group:has([data-command^="${command}"])`;

/**
 * Every control name → its element. null: no element of its own (the camera's screen is
 * found by `locateGuideTarget`), or the lab has no such control yet.
 * The type makes adding a name to lab-controls.ts without a place here a compile error.
 */
export const CONTROL_PATHS: Record<ControlTarget, ElementPath | null> = {
  'view.canvas': ['rt-scene-view', 'canvas'],
  'view.orbit-buttons': [...TOOLBAR, group('orbit-')],
  'view.pan-buttons': [...TOOLBAR, group('pan-')],
  'view.zoom-buttons': [...TOOLBAR, group('zoom-')],
  'view.fly-to-camera': [...TOOLBAR, '[data-command="fly"]'],
  'view.help': [...TOOLBAR, '[data-command="help"]'],
  'screen.grid': null,
  'scene-list.objects': ['rt-scene-list', '[role="option"][data-key^="object:"]'],
  'scene-list.lights': ['rt-scene-list', '[role="option"][data-key^="light:"]'],
  'object.color': ['rt-object-panel', '[name="color"]'],
  'object.ambient': ['rt-object-panel', '[name="ambient"]'],
  'object.diffuse': ['rt-object-panel', '[name="diffuse"]'],
  'object.specular': ['rt-object-panel', '[name="specular"]'],
  'object.shininess': ['rt-object-panel', '[name="shininess"]'],
  'object.transparent': ['rt-object-panel', '[name="transparent"]'],
  'object.refractive-index': ['rt-object-panel', '[name="refractiveIndex"]'],
  'object.presets': ['rt-object-panel', '.presets'],
  'light.type': ['rt-light-panel', '[name="type"]'],
  'light.color': ['rt-light-panel', '[name="color"]'],
  'light.intensity': ['rt-light-panel', '[name="intensity"]'],
  'light.ambient': ['rt-light-panel', '[name="ambient"]'],
  'light.diffuse': ['rt-light-panel', '[name="diffuse"]'],
  'light.specular': ['rt-light-panel', '[name="specular"]'],
  'light.distance-attenuation': ['rt-light-panel', '[name="distanceAttenuation"]'],
  'light.spot-angle': ['rt-light-panel', '[name="spotAngle"]'],
  'light.angle-attenuation': ['rt-light-panel', '[name="angleAttenuation"]'],
  'light.samples': ['rt-light-panel', '[name="samples"]'],
  'light.size': ['rt-light-panel', '[name="size"]'],
  'light.shape': ['rt-light-panel', '[name="shape"]'],
  'tracer.shadows': ['rt-tracer-panel', '[name="shadows"]'],
  'tracer.max-depth': ['rt-tracer-panel', '[name="maxDepth"]'],
  'tracer.background': ['rt-tracer-panel', '[name="background"]'],
  'tracer.supersampling': ['rt-tracer-panel', '[name="supersampling"]'],
  'tracer.sample-pattern': ['rt-tracer-panel', '[name="samplePattern"]'],
  'tracer.show-sample-points': ['rt-tracer-panel', '[name="showSamplePoints"]'],
  'tracer.pixels': ['rt-tracer-panel', '[name^="pixels."]'],
  'tracer.fov': ['rt-tracer-panel', '[name="fov"]'],
  'tracer.light-types': ['rt-tracer-panel', '[name^="lightTypes."]'],
  'tracer.dithering': ['rt-tracer-panel', '[name="dithering"]'],
  'rays.show': ['rt-ray-panel', '[name="showRays"]'],
  'rays.hide-no-hit': ['rt-ray-panel', '[name="hideNoHit"]'],
  'rays.hide-negligible': ['rt-ray-panel', '[name="hideNegligible"]'],
  'rays.negligible-threshold': ['rt-ray-panel', '[name="negligibleThreshold"]'],
  'rays.transparency': ['rt-ray-panel', '[name="transparency"]'],
  'rays.radius': ['rt-ray-panel', '[name="radius"]'],
  'rays.dynamic-radius': ['rt-ray-panel', '[name="dynamicRadius"]'],
  'rays.min-radius': ['rt-ray-panel', '[name="minRadius"]'],
  'rays.max-radius': ['rt-ray-panel', '[name="maxRadius"]'],
  'rays.contribution-color': ['rt-ray-panel', '[name="contributionColor"]'],
  'rays.color-blind': ['rt-ray-panel', '[name="colorBlindPalette"]'],
  'rays.animate': ['rt-ray-panel', '[name="animate"]'],
  'rays.legend': ['rt-ray-panel', 'rt-ray-legend'],
  'gizmo.translate': [...TOOLBAR, '[data-command="translate"]'],
  'gizmo.rotate': [...TOOLBAR, '[data-command="rotate"]'],
  'gizmo.scale': [...TOOLBAR, '[data-command="scale"]'],
  'gizmo.space': [...TOOLBAR, '[data-command="toggle-space"]'],
  'gizmo.snap': [...TOOLBAR, '[data-command="toggle-snap"]'],
  'screen-preview.grid': ['rt-screen-preview', '.grid'],
  'render.open': ['[data-command="render-open"]'],
  'render.start': ['rt-render-window', 'button.primary'],
  'render.cancel': ['rt-render-window'],
  'render.zoom': ['rt-render-window'],
  'render.save': ['rt-render-window'],
  'render.compare': ['rt-render-window', 'rt-image-compare'],
  'render.close': ['rt-render-window', '[data-command="render-close"]'],
  'add-remove.add-object': ['rt-scene-list', '.add'],
  'add-remove.add-light': ['rt-scene-list', '.add'],
  'add-remove.delete': ['rt-scene-list', '.actions'],
  'file.save': ['rt-file-panel', '[name="save"]'],
  'file.load': ['rt-file-panel', '[name="load"]'],
  'file.share': ['rt-file-panel', '[name="share"]'],
  'bvh.show': ['rt-bvh-panel', '[name="show"]'],
  'bvh.depth': ['rt-bvh-panel', '[name="depth"]'],
  'bvh.bounds': ['rt-bvh-panel', '[name="bounds"]'],
};

/** The panel whose element hosts a level panel's controls, for hiding the ones a level leaves out. */
export const PANEL_HOSTS = {
  object: 'rt-object-panel',
  light: 'rt-light-panel',
  tracer: 'rt-tracer-panel',
  rays: 'rt-ray-panel',
  bvh: 'rt-bvh-panel',
} as const satisfies Partial<Record<LabPanel, string>>;

/** Parses a guide target; undefined for a name that is not one (levels are validated, so only a bug gets here). */
export function locateGuideTarget(target: string): GuideLocation | undefined {
  if (!isGuideTarget(target)) return undefined;
  const colon = target.indexOf(':');
  if (target === 'screen.grid') return { kind: 'camera-screen' };
  if (colon < 0) {
    const path = CONTROL_PATHS[target as ControlTarget];
    return path ? { kind: 'element', path } : undefined;
  }
  const kind = target.slice(0, colon);
  const item = target.slice(colon + 1);
  if (kind === 'view.item') return { kind: 'view-item', id: item };
  if (kind === 'scene-list.item') {
    return { kind: 'element', path: ['rt-scene-list', `[role="option"]:is([data-key="object:${cssString(item)}"], [data-key="light:${cssString(item)}"])`] };
  }
  const match = /^(\d+),(\d+)$/.exec(item);
  return match ? { kind: 'pixel', column: Number(match[1]), row: Number(match[2]) } : undefined;
}

/**
 * CSS for a panel's shadow root that hides every control the level's `ui.controls` leaves
 * out (and sections left empty); '' when the panel shows all of its controls.
 */
export function hiddenControlsCss(panel: LabPanel, shown: readonly string[] | undefined): string {
  const host = (PANEL_HOSTS as Partial<Record<LabPanel, string>>)[panel];
  if (!host || !shown) return '';
  const selectorOf = (control: string) => {
    const path: ElementPath | null | undefined = (CONTROL_PATHS as Partial<Record<string, ElementPath | null>>)[`${panel}.${control}`];
    return path && path[0] === host ? path[path.length - 1] : undefined;
  };
  const kept = shown.flatMap((control) => selectorOf(control) ?? []);
  if (kept.length === 0) return '';
  const keep = kept.join(', ');
  // Only controls are hidden (an empty state's text stays), and sections left with no control shown.
  const controls = ':is([name], .presets)';
  return `rt-panel-section > ${controls}:not(${keep}) { display: none !important; }
rt-panel-section:has(> ${controls}):not(:has(> :is(${keep}))) { display: none !important; }`;
}

const GIZMO_CONTROLS = ['translate', 'rotate', 'scale', 'space', 'snap'] as const;

/**
 * CSS for the view toolbar's shadow root: the gizmo buttons a level leaves out (all of
 * them when it does not show the gizmo panel), and their groups once empty.
 */
export function hiddenToolbarCss(showGizmo: boolean, shown: readonly string[] | undefined): string {
  const hidden = GIZMO_CONTROLS.filter((control) => !showGizmo || (shown !== undefined && !shown.includes(control)));
  if (hidden.length === 0) return '';
  const selectors = hidden.map((control) => CONTROL_PATHS[`gizmo.${control}`]?.at(-1)).filter((selector) => selector !== undefined);
  const all = selectors.join(', ');
  // A group left with no button shows nothing but its frame: hide it too.
  return `${all} { display: none !important; }\n.group:has(${all}):not(:has(button:not(${all}))) { display: none !important; }`;
}

/** The centre of a scene item (object or light) by id, for `view.item:<id>`. */
export function itemPosition(scene: { objects: readonly { id: string; position: Vec3 }[]; lights: readonly { id: string; position: Vec3 }[] }, id: string): Vec3 | undefined {
  return (scene.objects.find((o) => o.id === id) ?? scene.lights.find((l) => l.id === id))?.position;
}

/** An id inside a quoted CSS attribute value (ids are kebab-case; quotes and backslashes are escaped anyway). */
function cssString(text: string): string {
  return text.replace(/["\\]/g, '\\$&');
}

// ─── On the page ─────────────────────────────────────────────────────────────

/** What finding a target needs of the lab besides its shadow root. */
export interface GuideStage {
  root: ShadowRoot;
  /** Where a world point is on the canvas (CSS px from its top-left), or null. */
  project(point: Vec3): { x: number; y: number } | null;
  canvas: HTMLElement | null;
  scene: { objects: readonly { id: string; position: Vec3 }[]; lights: readonly { id: string; position: Vec3 }[]; camera: { position: Vec3; pixels: readonly [number, number] | number[] } };
}

/** The elements at the end of `path`, through open shadow roots. */
export function elementsAt(root: ParentNode, path: ElementPath): Element[] {
  let scope: ParentNode = root;
  for (const [index, selector] of path.entries()) {
    if (index === path.length - 1) return [...scope.querySelectorAll(selector)];
    const next = scope.querySelector(selector);
    if (!next) return [];
    scope = next.shadowRoot ?? next;
  }
  return [];
}

/** The elements of a target, when it is an element on the page. */
export function guideElements(location: GuideLocation, stage: GuideStage): Element[] {
  switch (location.kind) {
    case 'element':
      return elementsAt(stage.root, location.path);
    case 'camera-screen':
      return elementsAt(stage.root, ['rt-screen-preview', '.grid']);
    case 'pixel': {
      const columns = stage.scene.camera.pixels[0] ?? 0;
      return elementsAt(stage.root, ['rt-screen-preview', `[data-index="${location.row * columns + location.column}"]`]);
    }
    case 'view-item':
      return [];
  }
}

/** Size of the ring around a point in the 3D view. */
const POINT_RING_PX = 64;

/** The box to ring, in viewport px; null while the target is not on the page (or behind the eye). */
export function guideRect(location: GuideLocation, stage: GuideStage): DOMRect | null {
  const boxes = guideElements(location, stage)
    .map((element) => element.getBoundingClientRect())
    .filter((box) => box.width > 0 && box.height > 0);
  if (boxes.length > 0) {
    const left = Math.min(...boxes.map((box) => box.left));
    const top = Math.min(...boxes.map((box) => box.top));
    return new DOMRect(left, top, Math.max(...boxes.map((box) => box.right)) - left, Math.max(...boxes.map((box) => box.bottom)) - top);
  }
  const point = location.kind === 'view-item' ? itemPosition(stage.scene, location.id) : location.kind === 'element' ? undefined : stage.scene.camera.position;
  const projected = point && stage.project(point);
  const canvas = stage.canvas?.getBoundingClientRect();
  if (!projected || !canvas) return null;
  return new DOMRect(canvas.left + projected.x - POINT_RING_PX / 2, canvas.top + projected.y - POINT_RING_PX / 2, POINT_RING_PX, POINT_RING_PX);
}

/** Makes the target visible: opens the collapsed sections around it and scrolls it into view. */
export function revealGuideTarget(location: GuideLocation, stage: GuideStage): void {
  const [first] = guideElements(location, stage);
  if (!first) return;
  for (let node: Node | null = first; node; node = node.parentNode ?? (node instanceof ShadowRoot ? node.host : null)) {
    if (node instanceof HTMLElement && node.localName === 'rt-panel-section' && !(node as HTMLElement & { open: boolean }).open) {
      (node as HTMLElement & { open: boolean }).open = true;
    }
  }
  first.scrollIntoView({ block: 'nearest', inline: 'nearest' });
}
