import type { BounceSampling, Vec3 } from '../scene/scene.ts';

/**
 * The sampling distribution of a diffuse bounce, as the 3D view draws it at a path's vertex
 * (path-tracing spec §5): around the normal, each direction at a distance from the vertex
 * proportional to the density it is drawn with. Cosine-weighted sampling has density
 * cosθ/π (Pharr, Jakob & Humphreys, pbrt 4th ed., §A.5.3, Malley's method): a lobe, a sphere
 * touching the surface at the vertex, longest along the normal and flat at the horizon.
 * Uniform sampling has density 1/(2π) (pbrt §A.5.2): a hemisphere, every direction alike.
 * Both on the same scale, so the cosine lobe reaches twice as far along the normal (1/π
 * against 1/(2π)) and the hemisphere twice as far as the lobe at 60° from it.
 */
export interface SamplingLobe {
  /** The vertex. */
  point: Vec3;
  /** The shading normal there, toward the side the path arrived from (path-recorder.ts). */
  normal: Vec3;
  sampling: BounceSampling;
  /** Metres from the vertex to the cosine lobe's tip (a density of 1/π). */
  size: number;
}

/** How far the view draws the cosine lobe's tip from its vertex, in metres: a fifth of the chapter's 2 m room. */
export const LOBE_SIZE = 0.4;

/** The density (per steradian) of a direction at cosθ from the normal; 0 below the surface. */
export function lobeDensity(sampling: BounceSampling, cosTheta: number): number {
  if (cosTheta < 0) return 0;
  return sampling === 'cosine' ? cosTheta / Math.PI : 1 / (2 * Math.PI);
}

/** How far from the vertex the lobe's surface lies in a direction at cosθ from the normal, in metres. */
export function lobeRadius(lobe: Pick<SamplingLobe, 'sampling' | 'size'>, cosTheta: number): number {
  return lobe.size * Math.PI * lobeDensity(lobe.sampling, cosTheta);
}
