/**
 * Light attenuation (spec §2), the same formulas as the Virtual Ray Tracer.
 */

/** The constant, linear and quadratic terms of the distance attenuation (spec §2). */
export const DISTANCE_ATTENUATION = { constant: 0.04, linear: 0.1, quadratic: 0.06 } as const;

/** Distance attenuation 1 / (0.04 + 0.1·d + 0.06·d²): constant, linear and quadratic terms. */
export function distanceAttenuation(d: number): number {
  const { constant, linear, quadratic } = DISTANCE_ATTENUATION;
  return 1 / (constant + linear * d + quadratic * d * d);
}

/**
 * Angle attenuation of a spot or area light: 0 outside the cone (α more than half the
 * cone's angle from the light's direction), else cos(α)^p.
 * @param cosAlpha cosine of the angle between the light's direction and the direction to the point
 * @param cosHalfAngle cosine of half the cone angle (spot: spotAngle/2; area: 90°, i.e. 0)
 * @param p the exponent (`angleAttenuation`); p = 0 gives a hard-edged cone
 */
export function angleAttenuation(cosAlpha: number, cosHalfAngle: number, p: number): number {
  if (cosAlpha < cosHalfAngle || cosAlpha <= 0) return 0;
  return p === 0 ? 1 : Math.pow(cosAlpha, p);
}
