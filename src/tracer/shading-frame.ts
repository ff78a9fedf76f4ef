import { Vector3 } from 'three';
import { discPointBuffer } from './disc-samples.ts';
import { Hit } from './hit.ts';
import type { Intersectable } from './intersectable.ts';
import { Ray } from './ray.ts';

/** Scratch space for one recursion depth, so tracing allocates nothing per ray. */
export class ShadingFrame {
  readonly hit = new Hit();
  /** The shading and geometric normals, turned toward the incoming ray. */
  readonly normal = new Vector3();
  readonly geometricNormal = new Vector3();
  readonly toViewer = new Vector3();
  readonly lightPoint = new Vector3();
  /** The unit direction to the light sample being shaded, and how far it is (ShadowTester reads both; fields: docs/performance.md, "Numbers passed to calls"). */
  readonly toLight = new Vector3();
  lightDistance = 0;
  readonly childDirection = new Vector3();
  readonly childOrigin = new Vector3();
  readonly childRay = new Ray();
  readonly childColor = new Vector3();
  /** Glossy rays: the ideal direction, the basis around it and the jittered disc points. */
  readonly ideal = new Vector3();
  readonly tangent = new Vector3();
  readonly bitangent = new Vector3();
  readonly discPoints = discPointBuffer();
  /** Whether the ray hit the outside of the surface (false: it is inside the object). */
  entering = true;
  /** How far the light travelled from the camera to this hit, over all the ray's bounces. */
  pathLength = 0;

  constructor(readonly depth: number) {}
}

/** The hit shape, if it is convex and `direction` leaves it from its outside (so cannot meet it again). */
export function leavingShape(frame: ShadingFrame, direction: Vector3): Intersectable | null {
  const shape = frame.hit.shape;
  return shape && shape.convex && frame.entering && frame.geometricNormal.dot(direction) > 0 ? shape : null;
}

/** The hit point moved ε off the surface, to the side `direction` leaves toward (no self-hits). */
export function offsetOrigin(frame: ShadingFrame, direction: Vector3, epsilon: number): Vector3 {
  const ng = frame.geometricNormal;
  const side = ng.dot(direction) >= 0 ? epsilon : -epsilon;
  return frame.childOrigin.copy(frame.hit.point).addScaledVector(ng, side);
}
