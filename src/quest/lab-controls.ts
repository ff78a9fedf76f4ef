/**
 * The lab's panels and controls by the stable names levels use: `ui.panels` says which
 * panels a level shows (early levels show few), `ui.controls` can narrow a panel to some of
 * its controls, and a task's `guide` names the control the hint ladder rings
 * ("tracer.supersampling"). The UI maps each name to its element; renaming one breaks
 * level files, so names only ever get added.
 */

/** The panels a level chooses from in `ui.panels`. */
export const UI_PANELS = [
  'scene-list',
  'object',
  'light',
  'tracer',
  'rays',
  'gizmo',
  'screen-preview',
  'render',
  'add-remove',
  'file',
  'bvh',
  'debugger',
] as const;
export type UiPanel = (typeof UI_PANELS)[number];

/** The 3D view with its buttons, and the camera's screen drawn in it: always on screen. */
export const ALWAYS_SHOWN = ['view', 'screen'] as const;
export type LabPanel = UiPanel | (typeof ALWAYS_SHOWN)[number];

/** Every panel's controls. */
export const LAB_CONTROLS = {
  view: ['canvas', 'orbit-buttons', 'pan-buttons', 'zoom-buttons', 'fly-to-camera', 'show-pixel-rays', 'help'],
  screen: ['grid'],
  'scene-list': ['objects', 'lights'],
  object: ['color', 'ambient', 'diffuse', 'specular', 'shininess', 'transparent', 'refractive-index', 'presets', 'roughness', 'glossy-samples', 'velocity'],
  light: [
    'type',
    'color',
    'intensity',
    'ambient',
    'diffuse',
    'specular',
    'distance-attenuation',
    'spot-angle',
    'angle-attenuation',
    'samples',
    'size',
    'shape',
  ],
  tracer: [
    'shadows',
    'max-depth',
    'background',
    'supersampling',
    'sample-pattern',
    'show-sample-points',
    'pixels',
    'fov',
    'light-types',
    'dithering',
    'encoding',
    'aperture',
    'focus-distance',
    'focus-on-selected',
    'lens-samples',
    'time-samples',
    'time-pattern',
    'integrator',
    'path-samples',
    'bounce-sampling',
    'light-sampling',
    'russian-roulette',
    'exposure',
  ],
  rays: [
    'show',
    'hide-no-hit',
    'hide-negligible',
    'negligible-threshold',
    'transparency',
    'radius',
    'dynamic-radius',
    'min-radius',
    'max-radius',
    'contribution-color',
    'color-blind',
    'animate',
    'legend',
    'color-by-time',
  ],
  gizmo: ['translate', 'rotate', 'scale', 'space', 'snap'],
  'screen-preview': ['grid'],
  render: ['open', 'start', 'cancel', 'zoom', 'save', 'compare', 'close', 'contrast'],
  'add-remove': ['add-object', 'add-light', 'delete'],
  file: ['save', 'load', 'share'],
  bvh: ['show', 'depth', 'bounds'],
  debugger: ['open', 'step', 'back', 'play', 'reset', 'code', 'equation', 'pixel', 'why-dark', 'close'],
} as const satisfies Record<LabPanel, readonly string[]>;

const PANELS = Object.keys(LAB_CONTROLS) as LabPanel[];

/** A panel's control ids, e.g. ControlOf<'light'> is 'type' | 'color' | … | 'spot-angle' | …. */
export type ControlOf<Panel extends LabPanel> = (typeof LAB_CONTROLS)[Panel][number];

/** "panel.control", e.g. "tracer.supersampling". */
export type ControlTarget = { [Panel in LabPanel]: `${Panel}.${ControlOf<Panel>}` }[LabPanel];

/**
 * The `data-guide` value of an element that is the control `targets` name
 * ("render.zoom render.compare"): a target that is no declared control fails to compile.
 */
export function guideIds(...targets: ControlTarget[]): string {
  return targets.join(' ');
}

export const CONTROL_TARGETS = PANELS.flatMap((panel) => LAB_CONTROLS[panel].map((control) => `${panel}.${control}` as ControlTarget));

/**
 * Targets that point at one thing in the scene rather than at a control:
 * `view.item:ball` (the object or light "ball" in the 3D view), `scene-list.item:ball`
 * (its row in the list) and `screen.pixel:3,2` (column 3, row 2 of the camera's screen).
 */
export const ITEM_TARGETS = ['view.item', 'scene-list.item', 'screen.pixel'] as const;
export type ItemTarget = `${(typeof ITEM_TARGETS)[number]}:${string}`;

export type GuideTarget = ControlTarget | ItemTarget;

export function isGuideTarget(text: string): text is GuideTarget {
  if ((CONTROL_TARGETS as readonly string[]).includes(text)) return true;
  const colon = text.indexOf(':');
  return colon > 0 && colon < text.length - 1 && (ITEM_TARGETS as readonly string[]).includes(text.slice(0, colon));
}

/** "tracer.supersampling" → panel "tracer", control "supersampling"; "view.item:ball" → "view", "item", "ball". */
export function partsOfTarget(target: GuideTarget): { panel: LabPanel; control: string; item?: string } {
  const [name, item] = target.split(/:(.*)/s, 2);
  const dot = name.indexOf('.');
  const panel = PANELS.find((candidate) => candidate === name.slice(0, dot)) ?? 'view';
  return { panel, control: name.slice(dot + 1), ...(item === undefined ? {} : { item }) };
}
