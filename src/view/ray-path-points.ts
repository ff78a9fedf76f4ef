import type { Vec3 } from '../scene/scene.ts';
import type { PixelTrace, RayNode } from '../tracer/ray-tree.ts';

/**
 * How far a ray that hit nothing counts when a pixel's rays are framed (metres): it is drawn
 * 10 m long towards the sky, and framing all of it would shrink the path that matters.
 */
export const MISS_REACH = 1;

/** Each of a pixel's rays as its start and end (a miss: MISS_REACH along it), parents before children. */
export function raySegments(trace: PixelTrace): [Vec3, Vec3][] {
  const segments: [Vec3, Vec3][] = [];
  const visit = (node: RayNode) => {
    const reach = node.hit ? node.length : Math.min(node.length, MISS_REACH);
    segments.push([node.origin, [0, 1, 2].map((axis) => node.origin[axis] + node.direction[axis] * reach) as Vec3]);
    node.children.forEach(visit);
  };
  trace.rays.forEach(visit);
  return segments;
}

/** Every point a pixel's rays start, end or fan out to (area cones' corners): what "show its rays" frames. */
export function rayPathPoints(trace: PixelTrace): Vec3[] {
  const corners: Vec3[] = [];
  const visit = (node: RayNode) => {
    if (node.corners) corners.push(...node.corners);
    node.children.forEach(visit);
  };
  trace.rays.forEach(visit);
  return [...raySegments(trace).flat(), ...corners];
}

/**
 * What a view framing `rays:<column>,<row>` fits: where the pixel's rays hit and turn, not the
 * way to them from the camera, nor the way to a lamp (a ray toward a light counts its first
 * MISS_REACH metres, like a ray that hit nothing): the bounces inside a glass block, not the
 * whole room they light.
 */
export function rayPathPointsFromHit(trace: PixelTrace): Vec3[] {
  const points: Vec3[] = [];
  const visit = (node: RayNode, root: boolean) => {
    const towardLight = node.type === 'light' || node.type === 'area-light';
    const reach = node.hit && !towardLight ? node.length : Math.min(node.length, MISS_REACH);
    const end = [0, 1, 2].map((axis) => node.origin[axis] + node.direction[axis] * reach) as Vec3;
    points.push(...(root ? [end] : [node.origin, end]));
    node.children.forEach((child) => visit(child, false));
  };
  trace.rays.forEach((root) => visit(root, true));
  return points;
}

/** A point on the canvas, in CSS px from its top-left. */
export interface CanvasPoint {
  x: number;
  y: number;
}

/** The trace's rays as segments on the canvas (`project` gives a world point's place, null behind the eye); none without a trace. */
export function raySegmentsOnCanvas(trace: PixelTrace | null, project: (point: Vec3) => CanvasPoint | null): { from: CanvasPoint; to: CanvasPoint }[] {
  if (!trace) return [];
  return raySegments(trace).flatMap(([start, end]) => {
    const from = project(start);
    const to = project(end);
    return from && to ? [{ from, to }] : [];
  });
}
