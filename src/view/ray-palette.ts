import type { Color } from '../scene/scene.ts';
import type { RayType } from '../tracer/ray-tree.ts';

/**
 * What a drawn line is coloured as, one legend entry each: a ray's type, except that every
 * ray that hit nothing is "no-hit" (red in VRT), area cones take the colour of the shadow rays
 * they merge ("light": shadow rays that reach the light, "shadow": blocked ones), and a ray
 * toward a light recorded with Shadows off is "untested" (no shadow ray was cast: it is only
 * the direction to the light). "normal" is no ray: the surface normal at a chosen pixel's hits.
 */
export type RayColorKey = 'primary' | 'light' | 'shadow' | 'untested' | 'reflect' | 'refract' | 'no-hit' | 'normal';

/** The legend's order: VRT's, with the direction not tested beside the shadow rays and the normal last. */
export const RAY_COLOR_KEYS: readonly RayColorKey[] = ['primary', 'light', 'shadow', 'untested', 'reflect', 'refract', 'no-hit', 'normal'];

/**
 * The legend's entries for a scene: every key, except "untested" while Shadows is on (nothing
 * is drawn so then, and naming it would answer level 4's question before it is asked).
 */
export function legendKeys(shadows: boolean): RayColorKey[] {
  return RAY_COLOR_KEYS.filter((key) => key !== 'untested' || !shadows);
}

/** Each key's index in RAY_COLOR_KEYS: the form the drawn segments store it in (a byte each). */
export const RAY_COLOR_KEY_INDEX = Object.fromEntries(RAY_COLOR_KEYS.map((key, index) => [key, index])) as Readonly<Record<RayColorKey, number>>;

export type RayPaletteName = 'vrt' | 'okabe-ito';

/** sRGB hex colours (as a designer writes them), by key. */
export type RayPalette = Readonly<Record<RayColorKey, string>>;

/**
 * The Virtual Ray Tracer's legend (spec §3), and two colours it has no ray for: amber for the
 * direction to a light that was not tested (near the light's yellow, but its own), magenta
 * for the normal (no ray has a purple hue).
 */
const VRT: RayPalette = {
  primary: '#70FFFB',
  light: '#FFE600',
  shadow: '#656565',
  untested: '#FF9A1F',
  reflect: '#008CFF',
  refract: '#00FF32',
  'no-hit': '#FF0000',
  normal: '#FF3DDB',
};

/**
 * The colour-blind-safe alternative: Okabe & Ito's eight colours ("Color Universal Design
 * (CUD): How to make figures and presentations that are friendly to colorblind people",
 * 2008; also Wong, Nature Methods 8:441, 2011), chosen near VRT's hues so the lesson's
 * words still fit (primary sky blue, light yellow, reflect blue, refract bluish green,
 * no-hit vermillion, the untested direction orange, the normal reddish purple). Shadow stays
 * a neutral grey, which every kind of colour vision sees as the same grey: it differs from
 * the others by lightness and lack of hue.
 */
const OKABE_ITO: RayPalette = {
  primary: '#56B4E9',
  light: '#F0E442',
  shadow: '#656565',
  untested: '#E69F00',
  reflect: '#0072B2',
  refract: '#009E73',
  'no-hit': '#D55E00',
  normal: '#CC79A7',
};

/**
 * Dash and gap along a drawn ray, in metres ([0, 0]: solid), in both palettes: a ray's type
 * is never told by its hue alone (WCAG 1.4.1). Light rays (yellow) and refracted ones (green)
 * differ by ΔE 5.5 under deuteranopia and 1.9 under protanopia in VRT's colours, no-hit red
 * and refract green are the classic red-green pair: refracted rays are dotted, no-hit rays
 * long-dashed, shadow rays dashed, reflected rays long dashes with short gaps; primary and
 * light rays, the most numerous, stay solid. The direction to a light that was not tested is
 * sparse dots, mostly gap: a faint hint of a line that no traced ray looks like. The normal,
 * a short arrow, is solid. The legend draws the same patterns.
 */
export const RAY_DASHES: Readonly<Record<RayColorKey, readonly [dash: number, gap: number]>> = {
  primary: [0, 0],
  light: [0, 0],
  shadow: [0.08, 0.05],
  untested: [0.03, 0.1],
  reflect: [0.12, 0.04],
  refract: [0.03, 0.03],
  'no-hit': [0.2, 0.08],
  normal: [0, 0],
};

/**
 * Keys whose dash gaps are painted GAP_FILL instead of left open. A blocked shadow ray is grey
 * (#656565, VRT's and spec §3's), and on the grey floor of the shadow levels it all but
 * vanished: light gaps between its grey dashes, like a barrier's stripes, stand out
 * on a light floor and on the dark theme's background alike. The legend draws them too.
 */
export const FILLED_GAP_KEYS: ReadonlySet<RayColorKey> = new Set(['shadow']);
export const GAP_FILL = '#F2F2F2';

/**
 * Keys drawn with a plate across their end (ray-extras.ts, for a chosen pixel): a blocked
 * shadow ray ends where something stops it, and the plate says "stopped here", not "arrived".
 */
export const STOPPED_KEYS: ReadonlySet<RayColorKey> = new Set(['shadow']);

export function rayPalette(name: RayPaletteName): RayPalette {
  return name === 'okabe-ito' ? OKABE_ITO : VRT;
}

export function paletteNameFor(colorBlindPalette: boolean): RayPaletteName {
  return colorBlindPalette ? 'okabe-ito' : 'vrt';
}

/** The legend entry a ray is drawn as (see RayColorKey); `untested`: RayNode.untested. */
export function rayColorKey(type: RayType, hit: boolean, untested = false): RayColorKey {
  if (!hit) return 'no-hit';
  if (untested) return 'untested';
  if (type === 'area-light') return 'light';
  if (type === 'area-shadow') return 'shadow';
  return type;
}

/**
 * `#RRGGBB` as RGB in 0..1, byte / 255. The lab shows colours as display values with no
 * gamma, like the ray tracer (lab-view.ts turns three.js's colour management off), so a
 * drawn ray looks exactly like its swatch in the legend.
 */
export function hexToColor(hex: string): Color {
  const value = Number.parseInt(hex.slice(1), 16);
  return [((value >> 16) & 255) / 255, ((value >> 8) & 255) / 255, (value & 255) / 255];
}

/** The palettes as colours, converted once: the visibility rules read them per update. */
const COLORS = new Map<RayPaletteName, Readonly<Record<RayColorKey, Color>>>(
  (['vrt', 'okabe-ito'] as const).map((name) => {
    const palette = rayPalette(name);
    return [name, Object.fromEntries(RAY_COLOR_KEYS.map((key) => [key, hexToColor(palette[key])])) as Record<RayColorKey, Color>];
  }),
);

export function rayColor(palette: RayPaletteName, key: RayColorKey): Color {
  return (COLORS.get(palette) as Record<RayColorKey, Color>)[key];
}
