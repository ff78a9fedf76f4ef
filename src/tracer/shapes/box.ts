import type { Vector3 } from 'three';
import type { Hit } from '../hit.ts';
import { Shape } from './shape.ts';

/** The unit cube, 1×1×1 centred on the origin. */
export class Box extends Shape {
  readonly convex = true;

  protected intersectLocal(o: Vector3, d: Vector3, tMax: number): number | null {
    // Slab test in object space; the exit distance is the hit when the ray starts inside.
    let ix = 1 / d.x;
    let t0 = (-0.5 - o.x) * ix;
    let t1 = (0.5 - o.x) * ix;
    let near = Math.min(t0, t1);
    let far = Math.max(t0, t1);
    ix = 1 / d.y;
    t0 = (-0.5 - o.y) * ix;
    t1 = (0.5 - o.y) * ix;
    near = Math.max(near, Math.min(t0, t1));
    far = Math.min(far, Math.max(t0, t1));
    ix = 1 / d.z;
    t0 = (-0.5 - o.z) * ix;
    t1 = (0.5 - o.z) * ix;
    near = Math.max(near, Math.min(t0, t1));
    far = Math.min(far, Math.max(t0, t1));
    if (!(near <= far) || far <= 0) return null;
    const t = near > 0 ? near : far;
    return t < tMax ? t : null;
  }

  protected localNormals(hit: Hit, geometric: Vector3, shading: Vector3): void {
    // The face is the axis on which the hit point lies farthest out.
    const p = hit.local;
    const ax = Math.abs(p.x);
    const ay = Math.abs(p.y);
    const az = Math.abs(p.z);
    if (ax >= ay && ax >= az) geometric.set(Math.sign(p.x), 0, 0);
    else if (ay >= az) geometric.set(0, Math.sign(p.y), 0);
    else geometric.set(0, 0, Math.sign(p.z));
    shading.copy(geometric);
  }
}
