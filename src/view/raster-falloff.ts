import { type Material, ShaderChunk } from 'three';
import { DISTANCE_ATTENUATION } from '../tracer/attenuation.ts';

/**
 * The tracer's light fall-off in the 3D view's shaders (spec §2, src/tracer/attenuation.ts).
 * Three.js lights know only `distance` and `decay` (A = 1/dᵈᵉᶜᵃʸ, windowed by the cut-off
 * distance) and a smoothstep penumbra, so the 3D view would light a scene differently from
 * the image. Every lit material of the view replaces those two functions of three.js's
 * `lights_pars_begin` chunk with the tracer's, and the raster lights carry the tracer's
 * values in the uniforms three.js already sends:
 * - `decay`: 0 for a light without distance attenuation, `FOLLOWS_DISTANCE` with it; A is
 *   then 1 / (0.04 + 0.1·d + 0.06·d²) at each fragment's own distance d.
 * - a spot light's `distance` (three.js's cut-off, unused now): the angle exponent p, so the
 *   cone gives cos(α)ᵖ inside and 0 outside, as the tracer's `angleAttenuation`.
 */

/** A light's `decay` when its distance attenuation is on (any value but 0 would do). */
export const FOLLOWS_DISTANCE = 1;

const { constant, linear, quadratic } = DISTANCE_ATTENUATION;

/**
 * The tracer's distance attenuation in GLSL, under three.js's name and signature. Each body
 * is statements that also read as JavaScript, so the tests run it against the tracer's.
 */
export const DISTANCE_FALLOFF_GLSL = `float getDistanceAttenuation( const in float lightDistance, const in float cutoffDistance, const in float decayExponent ) {
	if ( decayExponent == 0.0 ) return 1.0;
	return 1.0 / ( ${glslFloat(constant)} + ${glslFloat(linear)} * lightDistance + ${glslFloat(quadratic)} * lightDistance * lightDistance );
}`;

/** The tracer's cos(α)ᵖ inside the cone and 0 outside (or behind the light). */
export const ANGLE_FALLOFF_GLSL = `float getTracerAngleAttenuation( const in float coneCosine, const in float exponent, const in float angleCosine ) {
	if ( angleCosine < coneCosine || angleCosine <= 0.0 ) return 0.0;
	if ( exponent == 0.0 ) return 1.0;
	return pow( angleCosine, exponent );
}`;

const SPOT_CALL = 'getSpotAttenuation( spotLight.coneCos, spotLight.penumbraCos, angleCos )';
const TRACER_SPOT_CALL = 'getTracerAngleAttenuation( spotLight.coneCos, spotLight.distance, angleCos )';

/**
 * `lights_pars_begin` with the tracer's fall-off. Throws if three.js's chunk no longer has
 * the function or call it replaces, so an upgrade of three.js fails the tests, not the view.
 */
export function tracerLightsChunk(chunk: string = ShaderChunk.lights_pars_begin): string {
  const start = chunk.indexOf('float getDistanceAttenuation(');
  const end = start < 0 ? -1 : closingBrace(chunk, chunk.indexOf('{', start));
  if (end < 0 || !chunk.includes(SPOT_CALL)) throw new Error('three.js lights_pars_begin changed: the raster fall-off needs updating');
  const replaced = `${chunk.slice(0, start)}${DISTANCE_FALLOFF_GLSL}\n\n${ANGLE_FALLOFF_GLSL}${chunk.slice(end + 1)}`;
  return replaced.replace(SPOT_CALL, TRACER_SPOT_CALL);
}

let chunk: string | null = null;

/** Makes a lit material of the 3D view shade with the tracer's fall-off (see above). */
export function useTracerFalloff(material: Material): void {
  material.onBeforeCompile = (shader) => {
    chunk ??= tracerLightsChunk();
    shader.fragmentShader = shader.fragmentShader.replace('#include <lights_pars_begin>', chunk);
  };
  // Three.js caches programs by material type; this one differs from a plain one.
  material.customProgramCacheKey = () => 'tracer-falloff';
}

function closingBrace(text: string, open: number): number {
  let depth = 0;
  for (let i = open; i >= 0 && i < text.length; i++) {
    if (text[i] === '{') depth++;
    else if (text[i] === '}' && --depth === 0) return i;
  }
  return -1;
}

function glslFloat(value: number): string {
  return Number.isInteger(value) ? value.toFixed(1) : String(value);
}
