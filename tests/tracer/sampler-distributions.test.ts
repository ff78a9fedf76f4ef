/**
 * χ² tests of the distributions the tracer's samplers promise, over cells of equal
 * probability, with fixed keys so that the verdict is the same on every run. Each test also
 * runs a deliberately biased sampler through the same check and sees it fail, so the check
 * is known to be able to fail.
 */
import { Vector3 } from 'three';
import { describe, expect, it } from 'vitest';
import { discPointBuffer, jitteredDiscPoints } from '../../src/tracer/disc-samples.ts';
import { glossyDirection, perpendicularBasis } from '../../src/tracer/glossy.ts';
import { hashKey, RandomStream } from '../../src/tracer/sampler.ts';
import { chiSquare, chiSquareLimit } from '../support/chi-square.ts';

/** Rings × sectors: 64 cells, about 300 points expected in each. */
const RINGS = 8;
const SECTORS = 8;
const POINTS = 20_000;
const LIMIT = chiSquareLimit(RINGS * SECTORS - 1);

/** Fills `out` with q² points on the unit disc (x, y pairs) from `random`. */
type DiscSampler = (q: number, random: RandomStream, out: Float64Array) => Float64Array;

/**
 * The cell of a point by `areaFraction`, the share of the disc's area inside its radius (r²
 * on the unit disc, so the rings of equal area have radii √(k/RINGS)), and its angle `phi`.
 */
function cellOf(areaFraction: number, phi: number): number {
  const ring = Math.min(RINGS - 1, Math.floor(areaFraction * RINGS));
  const sector = Math.min(SECTORS - 1, Math.floor(((phi / (2 * Math.PI) + 1) % 1) * SECTORS));
  return ring * SECTORS + sector;
}

/** Counts of `POINTS` points of `sampler`, q² at a time from keys 0, 1, 2, …, in equal-area cells of the unit disc. */
function discCounts(sampler: DiscSampler, q: number): Uint32Array {
  const counts = new Uint32Array(RINGS * SECTORS);
  const random = new RandomStream();
  const points = discPointBuffer();
  for (let key = 0; key < POINTS / (q * q); key++) {
    sampler(q, random.reset(hashKey(7, key)), points);
    for (let i = 0; i < q * q; i++) {
      const [x, y] = [points[2 * i], points[2 * i + 1]];
      counts[cellOf(x * x + y * y, Math.atan2(y, x))]++;
    }
  }
  return counts;
}

/** A classic mistake: the radius uniform in [0, 1) instead of its square, which crowds the centre. */
const radiusUniform: DiscSampler = (q, random, out) => {
  for (let i = 0; i < q * q; i++) {
    const [r, phi] = [random.next(), 2 * Math.PI * random.next()];
    out[2 * i] = r * Math.cos(phi);
    out[2 * i + 1] = r * Math.sin(phi);
  }
  return out;
};

/** Points uniform in the square [−1, 1]², not mapped onto the disc. */
const squareNotDisc: DiscSampler = (q, random, out) => {
  for (let i = 0; i < 2 * q * q; i++) out[i] = 2 * random.next() - 1;
  return out;
};

describe('jittered disc points (lens and glossy samples): uniform in area on the unit disc', () => {
  it.each([1, 4, 8])('passes χ² over equal-area rings × sectors, q×q points at a time, q = %i', (q) => {
    const counts = discCounts(jitteredDiscPoints, q);
    expect(chiSquare(counts)).toBeLessThan(LIMIT);
  });

  it('every point lies on the disc', () => {
    const points = jitteredDiscPoints(8, new RandomStream().reset(1), discPointBuffer());
    for (let i = 0; i < 64; i++) expect(Math.hypot(points[2 * i], points[2 * i + 1])).toBeLessThanOrEqual(1);
  });

  it('a sampler with the radius uniform (not its square) fails the same test', () => {
    expect(chiSquare(discCounts(radiusUniform, 1))).toBeGreaterThan(10 * LIMIT);
  });
});

/**
 * The glossy lobe (glossy.ts; distribution-effects §2): direction normalize(R + ρ(a·T + b·B))
 * with (a, b) uniform on the unit disc. Its angle θ to R has tan θ = ρ·r, with r² uniform in
 * [0, 1), so P(θ ≤ t) = (tan t / ρ)²; its azimuth around R is uniform. (It is Cook's disc
 * spread, not a Phong cos^n lobe.) Cells of equal probability: rings of θ at
 * atan(ρ·√(k/RINGS)), sectors of azimuth measured in a basis of the test's own, not glossy.ts's.
 */
function glossyCounts(sampler: DiscSampler, r: Vector3, roughness: number, q: number): Uint32Array {
  const [t, b] = [new Vector3(), new Vector3()];
  perpendicularBasis(r, t, b);
  // The test's own axes around R, to measure azimuth by.
  const u = new Vector3(1, 0, 0).cross(r);
  if (u.lengthSq() < 1e-6) u.set(0, 1, 0).cross(r);
  u.normalize();
  const v = new Vector3().crossVectors(r, u);

  const counts = new Uint32Array(RINGS * SECTORS);
  const random = new RandomStream();
  const points = discPointBuffer();
  const direction = new Vector3();
  for (let key = 0; key < POINTS / (q * q); key++) {
    sampler(q, random.reset(hashKey(11, key)), points);
    for (let i = 0; i < q * q; i++) {
      glossyDirection(r, t, b, roughness, points[2 * i], points[2 * i + 1], direction);
      const cosTheta = direction.dot(r);
      const tanTheta = Math.sqrt(Math.max(0, 1 - cosTheta * cosTheta)) / cosTheta;
      counts[cellOf((tanTheta / roughness) ** 2, Math.atan2(direction.dot(v), direction.dot(u)))]++;
    }
  }
  return counts;
}

describe('glossy directions: the disc spread around the mirror direction', () => {
  const mirrors = {
    'up the normal': new Vector3(0, 1, 0),
    'straight down −z': new Vector3(0, 0, -1),
    slanted: new Vector3(1, -2, 0.5).normalize(),
  };

  for (const [name, r] of Object.entries(mirrors)) {
    it.each([0.2, 1])(`passes χ² over cells of equal probability, R ${name}, ρ = %s`, (roughness) => {
      expect(chiSquare(glossyCounts(jitteredDiscPoints, r, roughness, 3))).toBeLessThan(LIMIT);
    });
  }

  it('a spread from points on the square instead of the disc fails the same test', () => {
    expect(chiSquare(glossyCounts(squareNotDisc, mirrors.slanted, 0.5, 1))).toBeGreaterThan(5 * LIMIT);
  });
});
