import type { Vector3 } from 'three';

/**
 * Glossy directions (distribution-effects §2; Cook, Porter & Carpenter 1984): a rough
 * surface spreads its reflected (or refracted) rays around the ideal direction R as
 * normalize(R + ρ·(a·T + b·B)), with (a, b) jittered points on the unit disc and (T, B) an
 * orthonormal basis perpendicular to R. ρ = 0 gives R itself; ρ = 1 tilts the outermost
 * rays by 45°.
 */

/**
 * T and B, unit and perpendicular to unit `r` and to each other, by the branchless
 * construction of Duff et al., "Building an Orthonormal Basis, Revisited" (JCGT 2017).
 */
export function perpendicularBasis(r: Vector3, t: Vector3, b: Vector3): void {
  const sign = r.z >= 0 ? 1 : -1;
  const p = -1 / (sign + r.z);
  const q = r.x * r.y * p;
  t.set(1 + sign * r.x * r.x * p, sign * q, -sign * r.x);
  b.set(q, sign + r.y * r.y * p, -r.y);
}

/** normalize(r + ρ·(a·t + b·bAxis)) into `out`. */
export function glossyDirection(r: Vector3, t: Vector3, bAxis: Vector3, roughness: number, a: number, b: number, out: Vector3): Vector3 {
  return out
    .copy(r)
    .addScaledVector(t, roughness * a)
    .addScaledVector(bAxis, roughness * b)
    .normalize();
}
