import type { Color } from '../scene/scene.ts';

/**
 * One light's share of a hit's colour (ray-debugger spec §1), in the symbols of the
 * shading model (scene-and-tracer spec §2). For an area light the colours are the sums over
 * its n×n samples and the factors their means, so `diffuse` is not the product of the means.
 */
export interface LightTerms {
  lightId: string;
  /** la·Lc·C */
  ambient: Color;
  /** A: distance × angle factor, 1 when both are off (mean over the samples). */
  attenuation: number;
  /**
   * S: the share of the shadow rays cast toward the light that reached it, 1 when shadows
   * are off or no shadow ray was cast (the light was behind the surface or outside its
   * cone: NdotL = 0 or A = 0 already says so).
   */
  visibility: number;
  /** max(N·L, 0), as used (mean over the samples). */
  NdotL: number;
  /** max(R·V, 0) before the shininess power (mean over the samples; 0 where N·L ≤ 0). */
  RdotV: number;
  /** Σ I/n²·A·S·max(N·L,0)·kd·ld·Lc·C over the samples. */
  diffuse: Color;
  /** Σ I/n²·A·S·max(R·V,0)^n·ks·ls·Lc over the samples. */
  specular: Color;
  /** n²: samples taken (1 for point and spot lights). */
  samples: number;
}

/** What a reflected or refracted child adds: weight × the child's colour. */
export interface ChildTerm {
  /** ks for a mirror, kr or kt (Schlick) for glass, 1 for total internal reflection. */
  weight: number;
  /** The child ray's colour, as it came back (clamped). */
  color: Color;
}

/**
 * The parts a hit's colour is made of. Invariant (tests/tracer/shading-terms.test.ts): `sum`
 * is, bit for bit, ambient + for each light (ambient + diffuse + specular) + refract's
 * weight·color + reflect's weight·color, added in that order (the tracer's); the node's
 * colour is `sum` clamped to 0..1 per channel.
 */
export interface ShadingTerms {
  /** ka·C */
  ambient: Color;
  lights: LightTerms[];
  reflect: ChildTerm | null;
  refract: ChildTerm | null;
  /** Everything above, before clamping. */
  sum: Color;
  /** The surface would reflect or refract, but the ray is at the recursion depth (settings.maxDepth). */
  depthLimited: boolean;
}

/**
 * Gathers one light's terms sample by sample while the tracer shades (only when a tree
 * with terms is recorded: rendering never creates one).
 */
export class LightTermsRecorder {
  private attenuation = 0;
  private nDotL = 0;
  private rDotV = 0;
  private shadowRays = 0;
  private reached = 0;
  private samples = 0;

  constructor(
    private readonly lightId: string,
    private readonly ambient: Color,
  ) {}

  /** One sample: its factors as used, and whether a shadow ray was cast and reached the light. */
  sample(attenuation: number, nDotL: number, rDotV: number, shadowRay: 'none' | 'reached' | 'blocked'): void {
    this.samples++;
    this.attenuation += attenuation;
    this.nDotL += Math.max(nDotL, 0);
    this.rDotV += nDotL > 0 ? Math.max(rDotV, 0) : 0;
    if (shadowRay === 'none') return;
    this.shadowRays++;
    if (shadowRay === 'reached') this.reached++;
  }

  /** The light's terms, with the diffuse and specular sums the tracer added. */
  finish(diffuse: Color, specular: Color): LightTerms {
    const n = Math.max(this.samples, 1);
    return {
      lightId: this.lightId,
      ambient: this.ambient,
      attenuation: this.attenuation / n,
      visibility: this.shadowRays === 0 ? 1 : this.reached / this.shadowRays,
      NdotL: this.nDotL / n,
      RdotV: this.rDotV / n,
      diffuse,
      specular,
      samples: this.samples,
    };
  }
}
