import type { Vector3 } from 'three';

/**
 * Schlick's approximation of the Fresnel reflectance (Schlick 1994):
 * kr = r0 + (1 − r0)(1 − cosθ)⁵ with r0 = ((η − 1)/(η + 1))².
 * `cosTheta` must be the cosine on the less dense side of the surface (the incident angle
 * when entering glass, the transmitted angle when leaving it), otherwise leaving rays get
 * too little reflection near total internal reflection (de Greve, "Reflections and
 * Refractions in Ray Tracing", 2006).
 */
export function schlickReflectance(cosTheta: number, refractiveIndex: number): number {
  const r0 = ((refractiveIndex - 1) / (refractiveIndex + 1)) ** 2;
  return r0 + (1 - r0) * (1 - cosTheta) ** 5;
}

/**
 * Snell's law in vector form: the refracted direction of unit `d` through a surface with
 * unit normal `n` facing the incoming ray, for eta = n₁/n₂. Returns false (and leaves
 * `out` untouched) on total internal reflection.
 */
export function refract(d: Vector3, n: Vector3, eta: number, out: Vector3): boolean {
  const cosI = -d.dot(n);
  const k = 1 - eta * eta * (1 - cosI * cosI);
  if (k < 0) return false;
  out
    .copy(d)
    .multiplyScalar(eta)
    .addScaledVector(n, eta * cosI - Math.sqrt(k))
    .normalize();
  return true;
}

/**
 * η = n₁/n₂ for Snell's law at a surface of a material with refractive index `refractiveIndex`
 * in air (n = 1): 1/n for a ray entering it, n for a ray leaving it. With the normal turned
 * toward the incoming ray (the whitted integrator's shade), it is what `refract` takes.
 */
export function relativeIndex(entering: boolean, refractiveIndex: number): number {
  return entering ? 1 / refractiveIndex : refractiveIndex;
}

/** Mirror reflection of `d` about the unit normal `n`: d − 2(d·n)n. */
export function reflect(d: Vector3, n: Vector3, out: Vector3): Vector3 {
  return out.copy(d).addScaledVector(n, -2 * d.dot(n));
}
