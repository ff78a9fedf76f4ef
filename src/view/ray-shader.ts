/**
 * The rays' material: three.js's MeshBasicMaterial (unlit: a ray's colour is its type, not
 * its lighting) with two per-instance attributes added in onBeforeCompile:
 * - `aAlpha`: the instance's opacity (the built-in instanceColor is RGB only);
 * - `aGrowth` = (start, length) in metres of travel: the growth animation. The vertex
 *   shader scales the instance by clamp((uTravel − start) / length, 0, 1), where uTravel =
 *   elapsed time × speed is the one uniform that changes per frame. Cylinders grow along
 *   their axis (local z); cones are scaled as a whole about their apex;
 * - `aDash` = (dash, gap) in metres along a cylinder (0: solid; ray-palette.ts RAY_DASHES):
 *   the fragment shader discards the gaps, measured from the ray's start.
 */
import { DoubleSide, MeshBasicMaterial, type WebGLProgramParametersWithUniforms } from 'three';

export const ALPHA_ATTRIBUTE = 'aAlpha';
export const GROWTH_ATTRIBUTE = 'aGrowth';
export const DASH_ATTRIBUTE = 'aDash';

/** Travel that every ray has reached: the animation is off or over. */
export const FULLY_GROWN = 1e30;

/** The shared uniform: one object, so setting `.value` needs no recompile. */
export interface TravelUniform {
  value: number;
}

const VERTEX_HEAD = /* glsl */ `#include <common>
attribute float ${ALPHA_ATTRIBUTE};
attribute vec2 ${GROWTH_ATTRIBUTE};
uniform float uTravel;
varying float vRayAlpha;
#ifndef RAY_CONE
attribute vec2 ${DASH_ATTRIBUTE};
varying vec2 vRayDash;
varying float vRayAlong;
#endif`;

const VERTEX_GROW = /* glsl */ `#include <begin_vertex>
float rayGrown = clamp((uTravel - ${GROWTH_ATTRIBUTE}.x) / max(${GROWTH_ATTRIBUTE}.y, 1e-6), 0.0, 1.0);
#ifdef RAY_CONE
transformed *= rayGrown;
#else
transformed.z *= rayGrown;
vRayDash = ${DASH_ATTRIBUTE};
// Metres from the ray's start: local z (0..1) times the length the instance matrix gives the axis.
vRayAlong = position.z * length(instanceMatrix[2].xyz);
#endif
vRayAlpha = ${ALPHA_ATTRIBUTE};`;

const FRAGMENT_HEAD = /* glsl */ `#include <common>
varying float vRayAlpha;
#ifndef RAY_CONE
varying vec2 vRayDash;
varying float vRayAlong;
#endif`;

const FRAGMENT_ALPHA = /* glsl */ `#include <color_fragment>
diffuseColor.a *= vRayAlpha;
#ifndef RAY_CONE
if (vRayDash.x > 0.0 && mod(vRayAlong, vRayDash.x + vRayDash.y) > vRayDash.x) discard;
#endif`;

/** Replaces one `#include` of three's shader source, failing loudly if three renamed it. */
function patch(source: string, include: string, replacement: string): string {
  if (!source.includes(include)) throw new Error(`ray shader: three.js's shader has no ${include} any more`);
  return source.replace(include, replacement);
}

/** Applies the ray attributes to a compiled MeshBasicMaterial's shader (exported for the tests). */
export function patchRayShader(shader: Pick<WebGLProgramParametersWithUniforms, 'vertexShader' | 'fragmentShader' | 'uniforms'>, travel: TravelUniform): void {
  shader.uniforms.uTravel = travel;
  shader.vertexShader = patch(patch(shader.vertexShader, '#include <common>', VERTEX_HEAD), '#include <begin_vertex>', VERTEX_GROW);
  shader.fragmentShader = patch(patch(shader.fragmentShader, '#include <common>', FRAGMENT_HEAD), '#include <color_fragment>', FRAGMENT_ALPHA);
}

/**
 * A ray material. Cones are seen from inside and out (double-sided) in one pass: the
 * instances are not sorted anyway, and one pass keeps them at one draw call.
 */
export function createRayMaterial(kind: 'cylinder' | 'cone', travel: TravelUniform): MeshBasicMaterial {
  const material = new MeshBasicMaterial({ color: 0xffffff });
  // Always blended, as alpha comes per instance; ray-pool.ts turns depthWrite off for see-through rays.
  material.transparent = true;
  if (kind === 'cone') {
    material.defines = { RAY_CONE: '' };
    material.side = DoubleSide;
    material.forceSinglePass = true;
    material.depthWrite = false;
  }
  material.onBeforeCompile = (shader) => patchRayShader(shader, travel);
  return material;
}
