import { LAB_CONTROLS, type ControlOf, type LabPanel } from '../../../quest/lab-controls.ts';

/**
 * The panels whose elements name their controls after the state field they edit
 * (`refractiveIndex`) rather than by the level id (`refractive-index`): each control's name,
 * and the level id (quest/lab-controls.ts) it answers to, or null for a control levels
 * cannot name (position fields, the animation's speed). The names are the only ones these
 * panels accept (StorePanel's `ControlText.name`), so a control renamed in a panel, or here,
 * fails to compile instead of silently losing its hint ring and its place in a narrowed
 * level; `EVERY_ID_HAS_A_CONTROL` fails to compile while a level id has no control.
 * Grouped names ("pixels.columns", "lightTypes.area") share one id.
 */
export const CONTROL_NAMES = {
  object: {
    color: 'color',
    ambient: 'ambient',
    diffuse: 'diffuse',
    specular: 'specular',
    shininess: 'shininess',
    transparent: 'transparent',
    refractiveIndex: 'refractive-index',
    presets: 'presets',
    roughness: 'roughness',
    glossySamples: 'glossy-samples',
    velocity: 'velocity',
    position: null,
    rotation: null,
    scale: null,
  },
  light: {
    type: 'type',
    color: 'color',
    intensity: 'intensity',
    ambient: 'ambient',
    diffuse: 'diffuse',
    specular: 'specular',
    distanceAttenuation: 'distance-attenuation',
    spotAngle: 'spot-angle',
    angleAttenuation: 'angle-attenuation',
    samples: 'samples',
    size: 'size',
    shape: 'shape',
    position: null,
    rotation: null,
  },
  tracer: {
    shadows: 'shadows',
    maxDepth: 'max-depth',
    background: 'background',
    'lightTypes.point': 'light-types',
    'lightTypes.spot': 'light-types',
    'lightTypes.area': 'light-types',
    dithering: 'dithering',
    encoding: 'encoding',
    supersampling: 'supersampling',
    samplePattern: 'sample-pattern',
    showSamplePoints: 'show-sample-points',
    'pixels.columns': 'pixels',
    'pixels.rows': 'pixels',
    fov: 'fov',
    aperture: 'aperture',
    focusDistance: 'focus-distance',
    focusOnSelected: 'focus-on-selected',
    lensSamples: 'lens-samples',
    timeSamples: 'time-samples',
    timePattern: 'time-pattern',
    integrator: 'integrator',
    pathSamples: 'path-samples',
    bounceSampling: 'bounce-sampling',
    lightSampling: 'light-sampling',
    russianRoulette: 'russian-roulette',
    exposure: 'exposure',
    imageSize: null,
  },
  rays: {
    showRays: 'show',
    hideNoHit: 'hide-no-hit',
    hideNegligible: 'hide-negligible',
    negligibleThreshold: 'negligible-threshold',
    transparency: 'transparency',
    radius: 'radius',
    dynamicRadius: 'dynamic-radius',
    minRadius: 'min-radius',
    maxRadius: 'max-radius',
    contributionColor: 'contribution-color',
    colorBlindPalette: 'color-blind',
    animate: 'animate',
    legend: 'legend',
    colorByTime: 'color-by-time',
    animationSpeed: null,
    animatePixelByPixel: null,
    loop: null,
  },
} as const satisfies { [Panel in LabPanel]?: Record<string, ControlOf<Panel> | null> };

type NamedPanel = keyof typeof CONTROL_NAMES;

/** The names a panel's element gives its controls: its table's, or else the level ids themselves (debugger.why-dark). */
export type ControlName<Panel extends LabPanel> = (Panel extends NamedPanel ? keyof (typeof CONTROL_NAMES)[Panel] : ControlOf<Panel>) & string;

/** The level ids of `Panel` that no control of the table `Names` answers to. */
export type UnreachedIds<Panel extends LabPanel, Names> = Exclude<ControlOf<Panel>, Names[keyof Names]>;
type Unreached<Panel extends NamedPanel> = UnreachedIds<Panel, (typeof CONTROL_NAMES)[Panel]>;

/** Compiles only while every level id of a named panel has a control: a missing one is named in the error. */
export const EVERY_ID_HAS_A_CONTROL: { [Panel in NamedPanel]: [Unreached<Panel>] extends [never] ? true : { unreached: Unreached<Panel> } } = {
  object: true,
  light: true,
  tracer: true,
  rays: true,
};

function isNamedPanel(panel: LabPanel): panel is NamedPanel {
  return Object.hasOwn(CONTROL_NAMES, panel);
}

/** Whether `name` (read at run time, e.g. a solution's field) is one of `panel`'s control names. */
export function isControlName<Panel extends LabPanel>(panel: Panel, name: string): name is ControlName<Panel> {
  return isNamedPanel(panel) ? Object.hasOwn(CONTROL_NAMES[panel], name) : (LAB_CONTROLS[panel] as readonly string[]).includes(name);
}

/** The level id of `panel`'s control `name` ("refractiveIndex" → "refractive-index"), or undefined for one levels cannot name. */
export function controlIdOf<Panel extends LabPanel>(panel: Panel, name: ControlName<Panel>): ControlOf<Panel> | undefined {
  if (!isNamedPanel(panel)) return name as ControlOf<Panel>;
  const names: Readonly<Record<string, string | null>> = CONTROL_NAMES[panel];
  return (names[name] ?? undefined) as ControlOf<Panel> | undefined;
}
