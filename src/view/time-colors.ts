/**
 * Colours for a ray's shutter time τ in [0, 1) (distribution-effects §4: "rays of a selected
 * pixel can be coloured by their time"): the viridis ramp (van der Walt and Smith, matplotlib
 * 2015), dark violet at τ = 0 through teal to yellow at τ → 1. It is perceptually uniform and
 * readable with every kind of colour vision, and brightness alone already orders the times.
 */
const VIRIDIS: readonly [number, number, number][] = [
  [0.267, 0.005, 0.329],
  [0.229, 0.322, 0.546],
  [0.128, 0.567, 0.551],
  [0.369, 0.789, 0.383],
  [0.993, 0.906, 0.144],
];

/** The ramp's colour at τ (clamped to 0..1), linear between its five stops, into `out` at `at`. */
export function timeColor(time: number, out: Float32Array | number[], at = 0): void {
  const position = Math.min(1, Math.max(0, time)) * (VIRIDIS.length - 1);
  const stop = Math.min(VIRIDIS.length - 2, Math.floor(position));
  const f = position - stop;
  for (let axis = 0; axis < 3; axis++) out[at + axis] = VIRIDIS[stop][axis] + (VIRIDIS[stop + 1][axis] - VIRIDIS[stop][axis]) * f;
}

/**
 * The ramp as a CSS gradient from τ = 0 (left) to τ = 1 (right), for the ray legend's key.
 * The lab draws colours as display values with no gamma (ray-palette.ts, hexToColor) and CSS
 * interpolates in sRGB, so the key's colour at each τ is the colour a ray of that time is drawn in.
 */
export function timeGradient(): string {
  const last = VIRIDIS.length - 1;
  const stops = VIRIDIS.map(([r, g, b], i) => `rgb(${Math.round(r * 255)} ${Math.round(g * 255)} ${Math.round(b * 255)}) ${(100 * i) / last}%`);
  return `linear-gradient(90deg, ${stops.join(', ')})`;
}

/**
 * Metres along a ray in which every moment's stripe comes once. The rays of k moments often
 * run along one line (level 20: a pixel the moving ball never covers at its 4 moments), and
 * drawn on top of one another only the last one's colour showed. Each is drawn in stripes a
 * quarter of this long, placed by its moment τ: at the grid pattern's 4 moments the four
 * colours take turns along the line; a ray on its own is dashed in its colour.
 */
export const TIME_STRIPE_PERIOD = 0.4;

/** The share of each period a moment's stripe covers. */
export const TIME_STRIPE_SHARE = 0.25;

/**
 * A time ray's stripes in the rays' dash attribute (ray-shader.ts aDash): a negative first
 * number marks stripes, −(1 + τ), the second is the period. A type's dash is (dash, gap) ≥ 0.
 */
export function timeStripe(moment: number, out: Float32Array, at: number): void {
  out[at] = -(1 + Math.min(Math.max(moment, 0), 0.999999));
  out[at + 1] = TIME_STRIPE_PERIOD;
}
