/**
 * Which rays of the camera's screen are drawn, and how: the ray panel's rules as pure
 * functions over the traced ray trees (no three.js objects), so each rule is unit-tested and
 * the pool (ray-pool.ts) only copies the result into GPU buffers.
 *
 * The trees are flattened once per traced screen (flat-rays.ts); each option change is then
 * one linear pass. The result is struct-of-arrays typed arrays, reused between updates, so
 * a rebuild allocates nothing per ray.
 */
import type { RayViewOptions } from '../lab-state/lab-state.ts';
import type { ScreenRays } from '../render/screen-rays.ts';
import type { Color } from '../scene/scene.ts';
import type { RayNode } from '../tracer/ray-tree.ts';
import { flattenRays, type FlatRays, resized } from './flat-rays.ts';
import { paletteNameFor, RAY_COLOR_KEY_INDEX, RAY_COLOR_KEYS, rayColor } from './ray-palette.ts';
import { timeColor } from './time-colors.ts';

/**
 * Opacity at 100 % transparency. The option promises "almost invisible", not gone: a faint
 * trace still shows where the rays are and can still be hovered.
 */
export const MIN_ALPHA = 0.05;

/**
 * Contribution colour: how many decades of contribution fade a ray from its full colour
 * (100 %) to the faintest tone (0.1 % and below). Contributions span orders of magnitude
 * (a root of a 4×4 supersampled pixel already has 6 %, its grandchildren often < 1 %), so a
 * linear scale would leave every ray but the primaries looking equally dark.
 */
export const CONTRIBUTION_DECADES = 3;

/** The faintest tone of a ray in contribution colour: it keeps a hint of its type's hue. */
export const MIN_CONTRIBUTION_TONE = 0.15;

/**
 * How long the surface normal is drawn at a hit, in metres: short beside the rays (a level's
 * ball has a radius of 0.5 m), long enough for its arrowhead to read as a direction.
 */
export const NORMAL_LENGTH = 0.35;

const NORMAL_KEY = RAY_COLOR_KEY_INDEX.normal;

/** A growing list of drawn segments, as parallel typed arrays (index i is one segment). */
export class SegmentList {
  count = 0;
  /** xyz of the start: the ray's origin, or the apex (hit point) of a cone. */
  origin = new Float32Array(0);
  /** Unit xyz: along the ray, or from the apex to the centre of the cone's base. */
  direction = new Float32Array(0);
  /** Metres drawn: the ray's length (MISS_LENGTH for a miss), or apex to base centre. */
  length = new Float32Array(0);
  /** Cylinder radius in metres (unused for cones, whose base is the light). */
  radius = new Float32Array(0);
  /** RGB 0..1 (display values, as the lab draws them), 3 per segment. */
  color = new Float32Array(0);
  alpha = new Float32Array(0);
  /**
   * Metres of travel from the camera before this segment starts to grow (the animation):
   * 0 for primary rays, the parent's start + length for a child, plus the pixel's offset in
   * pixel-by-pixel mode.
   */
  start = new Float32Array(0);
  /** Index into RAY_COLOR_KEYS: the legend entry it is drawn as. */
  colorKey = new Uint8Array(0);
  /** Coloured by time: the ray's moment τ in [0, 1), where its stripes sit (time-colors.ts, timeStripe); −1 when not. */
  moment = new Float32Array(0);
  /** The pixel it belongs to, as y · columns + x. */
  pixel = new Int32Array(0);
  /** Cones only: the four corners of the base (the light, or across a glossy fan), 12 floats per cone (in RayNode.corners order). */
  corners = new Float32Array(0);
  /** The traced ray each segment draws (for hover); for a normal, the ray whose hit it stands on. */
  readonly nodes: RayNode[] = [];

  constructor(readonly withCorners: boolean) {}

  get capacity(): number {
    return this.length.length;
  }

  clear(): void {
    this.count = 0;
    this.nodes.length = 0;
  }

  /** Makes room for one more segment, doubling the arrays when full (never shrinks). */
  grow(): number {
    const i = this.count++;
    if (i < this.capacity) return i;
    const capacity = Math.max(64, this.capacity * 2);
    this.origin = resized(this.origin, capacity * 3);
    this.direction = resized(this.direction, capacity * 3);
    this.length = resized(this.length, capacity);
    this.radius = resized(this.radius, capacity);
    this.color = resized(this.color, capacity * 3);
    this.alpha = resized(this.alpha, capacity);
    this.start = resized(this.start, capacity);
    this.colorKey = resized(this.colorKey, capacity);
    this.moment = resized(this.moment, capacity);
    this.pixel = resized(this.pixel, capacity);
    if (this.withCorners) this.corners = resized(this.corners, capacity * 12);
    return i;
  }
}

/** Everything drawn for one state: cylinders for rays, cones for merged area rays and wide glossy fans. */
export class DrawnRays {
  readonly rays = new SegmentList(false);
  readonly cones = new SegmentList(true);
  /** Columns of the screen the segments' pixel indices refer to. */
  columns = 0;
  /** Metres of travel at which the last segment has fully grown (the animation's end). */
  travelEnd = 0;

  clear(): void {
    this.rays.clear();
    this.cones.clear();
    this.columns = 0;
    this.travelEnd = 0;
  }
}

/** What the rules need besides the options: the colour rays fade toward in contribution colour. */
export interface RayStyle {
  /** Default black ("darken by contribution"); the view may pass its background colour. */
  fadeTo: Color;
}

const DARKEN: RayStyle = { fadeTo: [0, 0, 0] };

/**
 * The rays to draw for `rays` under the panel's options:
 * - showRays off → nothing; a selected pixel → only that pixel's trees (none if it lies
 *   outside the traced screen, e.g. while a smaller screen is being traced).
 * - hideNoHit drops rays with hit = false (they have no children).
 * - hideNegligible drops a ray whose contribution is below the threshold (equal stays)
 *   together with its whole subtree: a child drawn without its parent would float
 *   unattached, and a child's share is normally at most its parent's anyway.
 * - Shadow rays carry black, so their own contribution is 0 by definition (spec §3); for
 *   the threshold, the dynamic radius and the contribution colour they use their parent's
 *   contribution instead: how much the point they start from matters. Otherwise "hide
 *   negligible" would hide every shadow, the very rays that explain a dark spot.
 * - Colour by type (palette per option), red for any ray that hit nothing; contribution
 *   colour mixes it toward `style.fadeTo` on a log scale (CONTRIBUTION_DECADES).
 * - alpha = 1 − transparency · (1 − MIN_ALPHA); radius fixed, or
 *   lerp(minRadius, maxRadius, contribution), which also works with min > max.
 * - colorByTime: a ray under a lens/time ray (distribution-effects §3) takes its time's
 *   colour (time-colors.ts) instead of its type's, and is drawn in stripes at its moment's
 *   place (`moment`), so the rays of several moments that run along one line show every
 *   moment's colour; rays without a time keep theirs.
 * - `kept`, a budget's choice while the learner edits (ray-budget.ts): a ray it leaves out
 *   (0, by its index in the flattened screen) is not drawn, nor its subtree.
 * - area-light / area-shadow nodes become cones from the hit point to the light's corners;
 *   so does a glossy fan of more than 25 rays that all hit one object (glossy-cone.ts),
 *   unless `glossyCones` is false (the ray debugger, which steps through each ray).
 * - A selected pixel's rays also get the surface normal at each of their hits (RayNode.normal):
 *   a short arrow (NORMAL_LENGTH) in the palette's normal colour, drawn right after its ray,
 *   shown and hidden with it, growing once the ray has arrived. A whole screen's hits would
 *   bristle with them, so only one pixel's rays have them.
 */
export function visibleRays(
  rays: ScreenRays | null,
  options: RayViewOptions,
  selectedPixel: readonly [number, number] | null,
  into = new DrawnRays(),
  style: RayStyle = DARKEN,
  glossyCones = true,
  kept: Uint8Array | null = null,
): DrawnRays {
  into.clear();
  if (!rays || !options.showRays) return into;
  into.columns = rays.columns;
  const flat = flattenRays(rays, glossyCones);
  const pass = new VisibilityPass(flat, into, options, style, selectedPixel !== null, kept);
  if (selectedPixel) {
    const [x, y] = selectedPixel;
    if (x >= 0 && y >= 0 && x < rays.columns && y < rays.rows) pass.pixel(y * rays.columns + x);
  } else {
    for (let p = 0; p < rays.columns * rays.rows; p++) pass.pixel(p);
  }
  into.travelEnd = pass.travelEnd;
  return into;
}

/** The contribution colour's tone in [MIN_CONTRIBUTION_TONE, 1]: 1 at 100 %, one third less per decade. */
export function contributionTone(contribution: number): number {
  if (!(contribution > 0)) return MIN_CONTRIBUTION_TONE;
  return Math.min(1, Math.max(MIN_CONTRIBUTION_TONE, 1 + Math.log10(contribution) / CONTRIBUTION_DECADES));
}

/** One application of the rules to a flattened screen, pixel by pixel. */
class VisibilityPass {
  /** The palette's colours, 3 per RAY_COLOR_KEYS entry. */
  private readonly colors = new Float32Array(RAY_COLOR_KEYS.length * 3);
  /** Scratch: the time colour of the ray being emitted. */
  private readonly timeRgb = new Float32Array(3);
  private readonly alpha: number;
  /** Travel added to every start of the current pixel (pixel-by-pixel animation). */
  private offset = 0;
  travelEnd = 0;

  constructor(
    private readonly flat: FlatRays,
    private readonly out: DrawnRays,
    private readonly options: RayViewOptions,
    private readonly style: RayStyle,
    /** Whether each hit's normal is drawn (one pixel's rays). */
    private readonly normals: boolean,
    /** Per flattened ray, 0 when a budget leaves it out (with its subtree); null: none does. */
    private readonly kept: Uint8Array | null,
  ) {
    const palette = paletteNameFor(options.colorBlindPalette);
    RAY_COLOR_KEYS.forEach((key, index) => this.colors.set(rayColor(palette, key), index * 3));
    this.alpha = 1 - clamp01(options.transparency) * (1 - MIN_ALPHA);
  }

  /** Draws pixel p's rays; in pixel-by-pixel mode the next pixel starts when this one has grown. */
  pixel(p: number): void {
    const { flat, options, kept } = this;
    const end = flat.pixelStart[p + 1];
    for (let i = flat.pixelStart[p]; i < end;) {
      const hidden =
        (options.hideNoHit && flat.hit[i] === 0) ||
        (options.hideNegligible && flat.contribution[i] < options.negligibleThreshold) ||
        (kept !== null && kept[i] === 0);
      if (hidden) {
        i = flat.subtreeEnd[i]; // with its whole subtree
      } else {
        this.emit(i, p);
        i++;
      }
    }
    if (options.animatePixelByPixel) this.offset = this.travelEnd;
  }

  private emit(i: number, p: number): void {
    const { flat, options, colors } = this;
    const { fadeTo } = this.style;
    const c = flat.cone[i];
    const list = c >= 0 ? this.out.cones : this.out.rays;
    const j = list.grow();
    list.nodes.push(flat.nodes[i]);
    for (let axis = 0; axis < 3; axis++) {
      list.origin[j * 3 + axis] = flat.origin[i * 3 + axis];
      list.direction[j * 3 + axis] = flat.direction[i * 3 + axis];
    }
    const length = flat.length[i];
    const start = flat.start[i] + this.offset;
    const contribution = flat.contribution[i];
    list.length[j] = length;
    list.start[j] = start;
    list.alpha[j] = this.alpha;
    list.pixel[j] = p;
    list.radius[j] = options.dynamicRadius ? options.minRadius + (options.maxRadius - options.minRadius) * clamp01(contribution) : options.radius;
    const key = flat.colorKey[i];
    list.colorKey[j] = key;
    const tone = options.contributionColor ? contributionTone(contribution) : 1;
    const time = flat.time[i];
    const byTime = options.colorByTime && time >= 0;
    if (byTime) timeColor(time, this.timeRgb);
    list.moment[j] = byTime ? time : -1;
    for (let axis = 0; axis < 3; axis++) {
      const base = byTime ? this.timeRgb[axis] : colors[key * 3 + axis];
      list.color[j * 3 + axis] = fadeTo[axis] + (base - fadeTo[axis]) * tone;
    }
    if (c >= 0) list.corners.set(flat.corners.subarray(c * 12, c * 12 + 12), j * 12);
    if (start + length > this.travelEnd) this.travelEnd = start + length;
    if (this.normals && c < 0 && flat.hit[i] === 1) this.emitNormal(flat.nodes[i], j);
  }

  /** The normal at the hit of ray segment `ray` (if its node recorded one), as a segment of its own. */
  private emitNormal(node: RayNode, ray: number): void {
    const normal = node.normal;
    if (!normal) return;
    const list = this.out.rays;
    const j = list.grow();
    list.nodes.push(node);
    const length = list.length[ray];
    for (let axis = 0; axis < 3; axis++) {
      list.origin[j * 3 + axis] = list.origin[ray * 3 + axis] + list.direction[ray * 3 + axis] * length;
      list.direction[j * 3 + axis] = normal[axis];
      // Not a ray: neither contribution nor time colours it.
      list.color[j * 3 + axis] = this.colors[NORMAL_KEY * 3 + axis];
    }
    list.length[j] = NORMAL_LENGTH;
    list.start[j] = list.start[ray] + length;
    list.alpha[j] = list.alpha[ray];
    list.radius[j] = list.radius[ray];
    list.pixel[j] = list.pixel[ray];
    list.colorKey[j] = NORMAL_KEY;
    if (list.start[j] + NORMAL_LENGTH > this.travelEnd) this.travelEnd = list.start[j] + NORMAL_LENGTH;
  }
}

function clamp01(value: number): number {
  return Math.min(1, Math.max(0, value));
}
