/**
 * The exact Fresnel reflectance of unpolarized light at a smooth boundary between two
 * dielectrics: the mean of the s- and p-polarized reflectances (Hecht, "Optics", §4.6.2;
 * pbrt-v4 §9.5.1, FrDielectric). Path mode's glass uses it; Whitted mode keeps Schlick's
 * approximation (fresnel.ts).
 * @param cosIncident cosine of the angle between the incoming ray and the normal on its own side, 0..1
 * @param eta n_t / n_i: the index of the side the ray goes into over the index of the side it comes from
 * @returns the reflected share, 1 under total internal reflection
 */
export function fresnelDielectric(cosIncident: number, eta: number): number {
  const sin2Transmitted = (1 - cosIncident * cosIncident) / (eta * eta);
  if (sin2Transmitted >= 1) return 1;
  const cosTransmitted = Math.sqrt(1 - sin2Transmitted);
  const parallel = (eta * cosIncident - cosTransmitted) / (eta * cosIncident + cosTransmitted);
  const perpendicular = (cosIncident - eta * cosTransmitted) / (cosIncident + eta * cosTransmitted);
  return (parallel * parallel + perpendicular * perpendicular) / 2;
}
