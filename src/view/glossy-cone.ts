/**
 * A glossy fan drawn as one cone (distribution-effects §4): past GLOSSY_CONE_RAYS rays that
 * all hit the same object, a fan of single lines is a tangle, so the lab draws one
 * translucent pyramid instead, like the merged area-light cone: apex at the hit, base across
 * the fan where its rays arrive. Unlike the area cone (merged by the tracer, whose sample
 * rays are leaves), a glossy ray carries a subtree, so the merging is the view's: the rays
 * the fan's rays cast (shadow, light, further bounces) are still drawn, from their own
 * hit points.
 */
import { Vector3 } from 'three';
import type { Vec3 } from '../scene/scene.ts';
import type { RayNode } from '../tracer/ray-tree.ts';

/** More glossy rays than this in one fan, all hitting one object, are drawn as a cone. */
export const GLOSSY_CONE_RAYS = 25;

/** One fan to draw as a cone: the node that stands for it (for hover) and the rays it replaces. */
export interface GlossyCone {
  /**
   * A `reflect` or `refract` node from the apex to the centre of the base, carrying the
   * fan's summed contribution and mean colour, with the fan's rays as its children.
   */
  node: RayNode;
  /** The base, in RayNode.corners order: c1 − c0 and c3 − c0 span it. */
  corners: [Vec3, Vec3, Vec3, Vec3];
}

/**
 * The fans among `children` (one per type: a rough glass has a reflected and a refracted
 * one) that are drawn as cones, by the first ray of each. Absorbed directions (into the
 * surface, length 0, never drawn) do not count and stay as they are.
 */
export function glossyCones(children: readonly RayNode[]): Map<RayNode, GlossyCone> | null {
  if (children.length <= GLOSSY_CONE_RAYS) return null;
  let cones: Map<RayNode, GlossyCone> | null = null;
  for (const type of ['reflect', 'refract'] as const) {
    const fan = children.filter((child) => child.type === type && child.glossy && !child.absorbed);
    if (fan.length <= GLOSSY_CONE_RAYS) continue;
    const objectId = fan[0].objectId;
    if (objectId === null || !fan.every((ray) => ray.hit && ray.objectId === objectId)) continue;
    cones ??= new Map();
    cones.set(fan[0], coneOf(type, fan));
  }
  return cones;
}

/**
 * The fan's axis a is its rays' mean direction; each ray d lands, on the plane across a at
 * the fan's mean depth L along a, at offsets L·(d·T, d·B)/(d·a) for (T, B) perpendicular to
 * a. The base is the rectangle around those landing points, so every ray of the fan passes
 * inside the pyramid.
 */
function coneOf(type: 'reflect' | 'refract', fan: readonly RayNode[]): GlossyCone {
  const apex = new Vector3(...fan[0].origin);
  const axis = new Vector3();
  for (const ray of fan) axis.add(direction.fromArray(ray.direction));
  axis.normalize();
  const t = new Vector3().crossVectors(Math.abs(axis.y) < 0.99 ? UP : RIGHT, axis).normalize();
  const b = new Vector3().crossVectors(axis, t);
  let depth = 0;
  let [uMin, uMax, vMin, vMax] = [Infinity, -Infinity, Infinity, -Infinity];
  for (const ray of fan) {
    direction.fromArray(ray.direction);
    const along = Math.max(direction.dot(axis), 1e-6);
    depth += along * ray.length;
    const u = direction.dot(t) / along;
    const v = direction.dot(b) / along;
    [uMin, uMax, vMin, vMax] = [Math.min(uMin, u), Math.max(uMax, u), Math.min(vMin, v), Math.max(vMax, v)];
  }
  depth /= fan.length;
  const at = (u: number, v: number) => axis.clone().addScaledVector(t, u).addScaledVector(b, v).multiplyScalar(depth).add(apex);
  const corners = [at(uMin, vMin), at(uMax, vMin), at(uMax, vMax), at(uMin, vMax)].map((corner) => corner.toArray()) as GlossyCone['corners'];
  const toCentre = at((uMin + uMax) / 2, (vMin + vMax) / 2).sub(apex);
  const length = toCentre.length();
  const color = fan
    .reduce<Vec3>((sum, ray) => [sum[0] + ray.color[0], sum[1] + ray.color[1], sum[2] + ray.color[2]], [0, 0, 0])
    .map((c) => c / fan.length) as Vec3;
  const node: RayNode = {
    type,
    origin: fan[0].origin,
    direction: toCentre.divideScalar(length).toArray(),
    length,
    hit: true,
    objectId: fan[0].objectId,
    lightId: null,
    color,
    contribution: fan.reduce((sum, ray) => sum + ray.contribution, 0),
    children: [...fan],
    glossy: true,
  };
  return { node, corners };
}

const UP = new Vector3(0, 1, 0);
const RIGHT = new Vector3(1, 0, 0);
/** Scratch: the direction of the ray being measured. */
const direction = new Vector3();
