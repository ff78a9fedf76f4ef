import { Box3, Vector3 } from 'three';
import type { Hit } from '../hit.ts';
import { Shape } from './shape.ts';

export const UNIT_BOUNDS = new Box3(new Vector3(-0.5, -0.5, -0.5), new Vector3(0.5, 0.5, 0.5));

/** The unit sphere: radius 0.5 at the origin (an ellipsoid once scaled). */
export class Sphere extends Shape {
  readonly convex = true;

  protected intersectLocal(o: Vector3, d: Vector3, tMax: number): number | null {
    // |o + t·d|² = r²  →  a·t² + 2·b·t + c = 0 with the half-b form of the quadratic.
    const a = d.dot(d);
    const b = o.dot(d);
    const c = o.dot(o) - 0.25;
    const disc = b * b - a * c;
    if (disc < 0) return null;
    const root = Math.sqrt(disc);
    let t = (-b - root) / a;
    if (t <= 0) t = (-b + root) / a; // the ray starts inside (refraction)
    return t > 0 && t < tMax ? t : null;
  }

  protected localNormals(hit: Hit, geometric: Vector3, shading: Vector3): void {
    geometric.copy(hit.local);
    shading.copy(hit.local);
  }
}
