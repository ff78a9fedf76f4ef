import type { Vector3 } from 'three';
import type { BounceSampling } from '../scene/scene.ts';
import { perpendicularBasis } from './glossy.ts';

const INV_TWO_PI = 1 / (2 * Math.PI);

/**
 * A direction in the hemisphere around unit normal `n` for a diffuse bounce, from two uniform
 * numbers u, v in [0, 1), written into `out`; returns its density per steradian.
 *
 * - 'cosine': Malley's method, a uniform point of the unit disc (Shirley & Chiu's concentric
 *   map) lifted onto the hemisphere, so directions come with density cosθ/π: Lambert's
 *   cosine is sampled exactly and cancels in the estimate (pbrt-v4 §A.5.3).
 * - 'uniform': every direction of the hemisphere alike, density 1/(2π) (pbrt-v4 §A.5.2).
 * Both are unbiased; they differ in noise, which is the "better guesses" lesson.
 */
export function sampleHemisphere(kind: BounceSampling, n: Vector3, u: number, v: number, tangent: Vector3, bitangent: Vector3, out: Vector3): number {
  perpendicularBasis(n, tangent, bitangent);
  let x: number;
  let y: number;
  let z: number;
  if (kind === 'cosine') {
    // concentricDisc (lights.ts) written out: its array was garbage and its call was not
    // inlined into the path loop (docs/performance.md, "Numbers passed to calls").
    const a = 2 * u - 1;
    const b = 2 * v - 1;
    if (a === 0 && b === 0) {
      x = 0;
      y = 0;
    } else {
      let r: number;
      let theta: number;
      if (Math.abs(a) > Math.abs(b)) {
        r = a;
        theta = (Math.PI / 4) * (b / a);
      } else {
        r = b;
        theta = Math.PI / 2 - (Math.PI / 4) * (a / b);
      }
      x = r * Math.cos(theta);
      y = r * Math.sin(theta);
    }
    z = Math.sqrt(Math.max(0, 1 - x * x - y * y));
  } else {
    z = u;
    const r = Math.sqrt(Math.max(0, 1 - z * z));
    const phi = 2 * Math.PI * v;
    x = r * Math.cos(phi);
    y = r * Math.sin(phi);
  }
  // n·z + tangent·x + bitangent·y, normalized, on plain numbers in the order of the Vector3
  // methods it stands for (copy, multiplyScalar, addScaledVector twice, normalize).
  const dx = n.x * z + tangent.x * x + bitangent.x * y;
  const dy = n.y * z + tangent.y * x + bitangent.y * y;
  const dz = n.z * z + tangent.z * x + bitangent.z * y;
  const inverseLength = 1 / (Math.sqrt(dx * dx + dy * dy + dz * dz) || 1);
  out.x = dx * inverseLength;
  out.y = dy * inverseLength;
  out.z = dz * inverseLength;
  return hemisphereDensity(kind, z);
}

/** The density per steradian of a direction at cosθ from the normal, for `kind`. */
export function hemisphereDensity(kind: BounceSampling, cosTheta: number): number {
  if (cosTheta <= 0) return 0;
  return kind === 'cosine' ? cosTheta / Math.PI : INV_TWO_PI;
}
