/**
 * The rays' material: three.js's MeshBasicMaterial (unlit: a ray's colour is its type, not
 * its lighting) with two per-instance attributes added in onBeforeCompile:
 * - `aAlpha`: the instance's opacity (the built-in instanceColor is RGB only);
 * - `aGrowth` = (start, length) in metres of travel: the growth animation. The vertex
 *   shader scales the instance by clamp((uTravel − start) / length, 0, 1), where uTravel =
 *   elapsed time × speed is the one uniform that changes per frame. Rays grow along their
 *   axis (local z); cones are scaled as a whole about their apex;
 * - a ray is a ribbon turned to face the eye (ray-pool.ts ribbonGeometry): its two long
 *   edges lie on either side of the axis, perpendicular to both the axis and the line of
 *   sight, so it covers what a cylinder of its radius would. An unlit ray looks the same
 *   either way, and a CPU rasterizer draws 2 long thin triangles instead of a six-sided
 *   cylinder's 6 in front (docs/benchmark-log.md, ninth round);
 * - a minimum width on screen: a ray thinner than RAY_MIN_WIDTH_PX at its depth is
 *   widened to it, so a 1 cm ray stays visible in a scene seen from 10 m (uViewHeight is the
 *   canvas height in CSS px, set before each draw);
 * - `aDash` = (dash, gap) in metres along a ray (0: solid; ray-palette.ts RAY_DASHES):
 *   the fragment shader discards the gaps, measured from the ray's start; a negative gap is
 *   painted GAP_FILL instead (FILLED_GAP_KEYS: the blocked shadow ray's light stripes). A ray
 *   coloured by time has (−(1 + τ), period) instead (time-colors.ts timeStripe): it keeps only
 *   the stripes a quarter period long that start τ of the way into each period.
 *
 * Two variants draw one pixel's rays more plainly (ray-extras.ts), from the cylinders' own
 * instances: `arrow` puts an arrowhead of a fixed size on screen along each ray, pointing the
 * way it travels, drawn over everything: its tip at `aArrowAt` of the grown length (ARROW_AT,
 * a little past halfway, for a ray; its end for a normal, an arrow like a textbook's vector); `hidden` draws, faintly, the parts of the rays that objects
 * hide (it passes only where something nearer was drawn: depth test "greater"); `stop` puts a
 * plate of a fixed size on screen across the end of each ray whose `aStop` is 1 (a blocked
 * shadow ray, ray-palette.ts STOPPED_KEYS) once it has grown to that end, over everything.
 */
import { DoubleSide, GreaterDepth, MeshBasicMaterial, Vector2, type WebGLProgramParametersWithUniforms } from 'three';
import { GAP_FILL, hexToColor, type RayColorKey } from './ray-palette.ts';
import { TIME_STRIPE_SHARE } from './time-colors.ts';

export const ALPHA_ATTRIBUTE = 'aAlpha';
export const GROWTH_ATTRIBUTE = 'aGrowth';
export const DASH_ATTRIBUTE = 'aDash';
export const ARROW_AT_ATTRIBUTE = 'aArrowAt';
export const STOP_ATTRIBUTE = 'aStop';

/** The thinnest a ray is drawn, in CSS px (issue 9: readable at a level's starting view). */
export const RAY_MIN_WIDTH_PX = 3;

/** An arrowhead's size on screen, in CSS px: plainly a head on a 3 px ray, small beside an object. */
export const ARROW_LENGTH_PX = 14;
export const ARROW_WIDTH_PX = 10;

/**
 * The plate across a stopped ray's end, in CSS px: as wide as an arrowhead is long, so it
 * reads as a bar across the ray (⊣) seen from the side, a disc seen along it.
 */
export const STOP_WIDTH_PX = 14;
export const STOP_THICKNESS_PX = 3;

/** Where along its grown part a ray's arrowhead points from (its tip), as a share of it. */
export const ARROW_AT = 0.55;

/** Where a drawn line of that legend entry has its arrowhead's tip: a normal's at its end. */
export function arrowAt(key: RayColorKey): number {
  return key === 'normal' ? 1 : ARROW_AT;
}

/** How strongly the hidden parts of a chosen pixel's rays show through what hides them. */
export const HIDDEN_ALPHA = 0.35;

/** Travel that every ray has reached: the animation is off or over. */
export const FULLY_GROWN = 1e30;

/** A shared uniform: one object, so setting `.value` needs no recompile. */
export interface TravelUniform {
  value: number;
}

/** The canvas height in CSS px, shared like the travel. */
export type ViewHeightUniform = TravelUniform;

const VERTEX_HEAD = /* glsl */ `#include <common>
attribute float ${ALPHA_ATTRIBUTE};
attribute vec2 ${GROWTH_ATTRIBUTE};
uniform float uTravel;
uniform float uViewHeight;
varying float vRayAlpha;
#if defined(RAY_ARROW)
attribute float ${ARROW_AT_ATTRIBUTE};
#endif
#if defined(RAY_STOP)
attribute float ${STOP_ATTRIBUTE};
#endif
#if !defined(RAY_CONE) && !defined(RAY_ARROW) && !defined(RAY_STOP)
attribute vec2 ${DASH_ATTRIBUTE};
varying vec2 vRayDash;
varying float vRayAlong;
#endif`;

const VERTEX_GROW = /* glsl */ `#include <begin_vertex>
float rayGrown = clamp((uTravel - ${GROWTH_ATTRIBUTE}.x) / max(${GROWTH_ATTRIBUTE}.y, 1e-6), 0.0, 1.0);
#if defined(RAY_CONE)
transformed *= rayGrown;
#elif defined(RAY_ARROW)
// The head's tip aArrowAt of the way along the grown ray; its size is fixed in screen pixels
// (at the tip's depth), but never longer than half of what has grown.
vec4 rayTipView = modelViewMatrix * instanceMatrix * vec4(0.0, 0.0, ${ARROW_AT_ATTRIBUTE} * rayGrown, 1.0);
float rayPixel = 2.0 * max(-rayTipView.z, 1e-4) / (projectionMatrix[1][1] * max(uViewHeight, 1.0));
float rayLength = max(length((modelViewMatrix * instanceMatrix * vec4(0.0, 0.0, 1.0, 0.0)).xyz), 1e-6);
float rayRadius = max(length((modelViewMatrix * instanceMatrix * vec4(1.0, 0.0, 0.0, 0.0)).xyz), 1e-9);
float headLength = min(${ARROW_LENGTH_PX.toFixed(1)} * rayPixel, 0.5 * rayLength * rayGrown);
float headRadius = 0.5 * ${ARROW_WIDTH_PX.toFixed(1)} * rayPixel * headLength / (${ARROW_LENGTH_PX.toFixed(1)} * rayPixel);
transformed = vec3(position.xy * headRadius / rayRadius, ${ARROW_AT_ATTRIBUTE} * rayGrown + position.z * headLength / rayLength);
#elif defined(RAY_STOP)
// The plate at the ray's end, its size fixed in screen pixels at that depth; a ray that is not
// stopped (aStop 0), or has not yet grown to its end, shrinks it to a point: nothing is drawn.
vec4 rayEndView = modelViewMatrix * instanceMatrix * vec4(0.0, 0.0, 1.0, 1.0);
float rayPixel = 2.0 * max(-rayEndView.z, 1e-4) / (projectionMatrix[1][1] * max(uViewHeight, 1.0));
float rayLength = max(length((modelViewMatrix * instanceMatrix * vec4(0.0, 0.0, 1.0, 0.0)).xyz), 1e-6);
float rayRadius = max(length((modelViewMatrix * instanceMatrix * vec4(1.0, 0.0, 0.0, 0.0)).xyz), 1e-9);
float stopShown = ${STOP_ATTRIBUTE} * step(1.0, rayGrown);
transformed = vec3(position.xy * stopShown * 0.5 * ${STOP_WIDTH_PX.toFixed(1)} * rayPixel / rayRadius, 1.0 + position.z * stopShown * ${STOP_THICKNESS_PX.toFixed(1)} * rayPixel / rayLength);
#else
// The ribbon's vertex: position.z along the grown axis, position.x = ±1 across it.
vec3 rayPointView = (modelViewMatrix * instanceMatrix * vec4(0.0, 0.0, position.z * rayGrown, 1.0)).xyz;
vec3 rayAxisView = (modelViewMatrix * instanceMatrix * vec4(0.0, 0.0, 1.0, 0.0)).xyz;
// A pixel at view depth d spans 2 d tan(fov / 2) / H, and projectionMatrix[1][1] = 1 / tan(fov / 2).
float rayPixel = 2.0 * max(-rayPointView.z, 1e-4) / (projectionMatrix[1][1] * max(uViewHeight, 1.0));
float rayRadius = length((modelViewMatrix * instanceMatrix * vec4(1.0, 0.0, 0.0, 0.0)).xyz);
// Across the axis and across the line of sight from the eye (the view's origin) to the point.
vec3 raySide = cross(rayAxisView, rayPointView);
// Seen straight along its axis a ray shows no length, only its width: any side will do.
if (dot(raySide, raySide) <= 1e-12 * dot(rayAxisView, rayAxisView) * dot(rayPointView, rayPointView)) raySide = cross(rayAxisView, abs(rayAxisView.y) < 0.9 * length(rayAxisView) ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0));
// A ray of length 0 has no side at all: its ribbon stays a point (normalize would give NaN).
float raySideLength = length(raySide);
vec3 rayAcross = raySideLength > 0.0 ? raySide / raySideLength : vec3(0.0);
vec3 rayViewPosition = rayPointView + rayAcross * position.x * max(rayRadius, 0.5 * ${RAY_MIN_WIDTH_PX.toFixed(1)} * rayPixel);
vRayDash = ${DASH_ATTRIBUTE};
// Metres from the ray's start: local z (0..1) times the length the instance matrix gives the axis.
vRayAlong = position.z * length(instanceMatrix[2].xyz);
#endif
vRayAlpha = ${ALPHA_ATTRIBUTE};`;

/** A ribbon's vertex is placed in view space already (VERTEX_GROW); cones and arrowheads go through three's own projection. */
const VERTEX_PROJECT = /* glsl */ `#if defined(RAY_CONE) || defined(RAY_ARROW) || defined(RAY_STOP)
#include <project_vertex>
#else
vec4 mvPosition = vec4(rayViewPosition, 1.0);
gl_Position = projectionMatrix * mvPosition;
#endif`;

const FRAGMENT_HEAD = /* glsl */ `#include <common>
varying float vRayAlpha;
#if !defined(RAY_CONE) && !defined(RAY_ARROW) && !defined(RAY_STOP)
varying vec2 vRayDash;
varying float vRayAlong;
#endif`;

const FRAGMENT_ALPHA = /* glsl */ `#include <color_fragment>
diffuseColor.a *= vRayAlpha;
#ifdef RAY_HIDDEN
diffuseColor.a *= ${HIDDEN_ALPHA.toFixed(2)};
#endif
#if !defined(RAY_CONE) && !defined(RAY_ARROW) && !defined(RAY_STOP)
if (vRayDash.x < 0.0) {
  if (fract(vRayAlong / vRayDash.y + vRayDash.x + 1.0) > ${TIME_STRIPE_SHARE.toFixed(2)}) discard;
} else if (vRayDash.x > 0.0 && mod(vRayAlong, vRayDash.x + abs(vRayDash.y)) > vRayDash.x) {
  if (vRayDash.y >= 0.0) discard;
  diffuseColor.rgb = vec3(${hexToColor(GAP_FILL)
    .map((c) => c.toFixed(4))
    .join(', ')});
}
#endif`;

const drawingSize = new Vector2();

/** Replaces one `#include` of three's shader source, failing loudly if three renamed it. */
function patch(source: string, include: string, replacement: string): string {
  if (!source.includes(include)) throw new Error(`ray shader: three.js's shader has no ${include} any more`);
  return source.replace(include, replacement);
}

/** Applies the ray attributes to a compiled MeshBasicMaterial's shader (exported for the tests). */
export function patchRayShader(
  shader: Pick<WebGLProgramParametersWithUniforms, 'vertexShader' | 'fragmentShader' | 'uniforms'>,
  travel: TravelUniform,
  viewHeight: ViewHeightUniform,
): void {
  shader.uniforms.uTravel = travel;
  shader.uniforms.uViewHeight = viewHeight;
  const vertex = patch(patch(shader.vertexShader, '#include <common>', VERTEX_HEAD), '#include <begin_vertex>', VERTEX_GROW);
  shader.vertexShader = patch(vertex, '#include <project_vertex>', VERTEX_PROJECT);
  shader.fragmentShader = patch(patch(shader.fragmentShader, '#include <common>', FRAGMENT_HEAD), '#include <color_fragment>', FRAGMENT_ALPHA);
}

/**
 * A ray material. Cones are seen from inside and out (double-sided) in one pass: the
 * instances are not sorted anyway, and one pass keeps them at one draw call.
 */
export function createRayMaterial(
  kind: 'cylinder' | 'cone' | 'arrow' | 'hidden' | 'stop',
  travel: TravelUniform,
  viewHeight: ViewHeightUniform,
): MeshBasicMaterial {
  const material = new MeshBasicMaterial({ color: 0xffffff });
  // Always blended, as alpha comes per instance; ray-pool.ts turns depthWrite off for see-through rays.
  material.transparent = true;
  if (kind === 'cone') {
    material.defines = { RAY_CONE: '' };
    material.side = DoubleSide;
    material.forceSinglePass = true;
    material.depthWrite = false;
  } else if (kind === 'arrow' || kind === 'stop') {
    material.defines = kind === 'arrow' ? { RAY_ARROW: '' } : { RAY_STOP: '' };
    // Over everything: a head behind the camera's screen or an object still says which way its
    // ray goes, and a plate on the far side of the ball that blocks a shadow ray still shows.
    material.depthTest = false;
    material.depthWrite = false;
  } else if (kind === 'hidden') {
    material.defines = { RAY_HIDDEN: '' };
    material.depthFunc = GreaterDepth;
    material.depthWrite = false;
  }
  if (kind === 'cylinder' || kind === 'hidden') {
    // A ribbon turns to the eye, so which of its faces is in front depends on the view:
    // both are drawn, in one pass.
    material.side = DoubleSide;
    material.forceSinglePass = true;
  }
  material.onBeforeCompile = (shader) => patchRayShader(shader, travel, viewHeight);
  material.onBeforeRender = (renderer) => {
    viewHeight.value = renderer.getSize(drawingSize).y;
  };
  return material;
}
