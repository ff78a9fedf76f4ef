import { Box3, Vector3 } from 'three';
import type { Hit } from '../hit.ts';
import { Shape } from './shape.ts';

export const PLANE_BOUNDS = new Box3(new Vector3(-0.5, 0, -0.5), new Vector3(0.5, 0, 0.5));

/** The unit square in the XZ plane, normal +Y; hit from both sides (spec §1). */
export class Plane extends Shape {
  readonly convex = true;

  protected intersectLocal(o: Vector3, d: Vector3, tMax: number): number | null {
    if (d.y === 0) return null;
    const t = -o.y / d.y;
    if (!(t > 0 && t < tMax)) return null;
    const x = o.x + t * d.x;
    const z = o.z + t * d.z;
    return Math.abs(x) <= 0.5 && Math.abs(z) <= 0.5 ? t : null;
  }

  protected localNormals(_hit: Hit, geometric: Vector3, shading: Vector3): void {
    geometric.set(0, 1, 0);
    shading.set(0, 1, 0);
  }
}
