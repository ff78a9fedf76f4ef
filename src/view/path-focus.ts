/**
 * A pixel's sample paths (path mode) as ray trees the 3D view already knows how to draw
 * (ray-focus.ts): each path one tree of segments, camera ray first, each bounce a reflected
 * or refracted ray, each light sample a light ray (reached) or a shadow ray (blocked) from
 * the vertex where it was taken. A segment's width follows the path's throughput along it
 * (how much of the light it brings back reaches the pixel). Pure: the debugger builds the
 * focus, the pool draws it.
 */
import type { BounceSampling, Color } from '../scene/scene.ts';
import type { LabPaths } from '../tracer/lab-paths.ts';
import type { PathVertex } from '../tracer/path-recorder.ts';
import type { RayNode, RayType } from '../tracer/ray-tree.ts';
import type { RayFocus } from './ray-focus.ts';
import { LOBE_SIZE } from './sampling-lobe.ts';

/** The paths as trees, and each path's rays by the vertex they arrive at or start from. */
export interface PathTrees {
  /** The trees as one pixel's trace: one root (the camera ray) per path. */
  trace: { pixel: [number, number]; color: Color; rays: RayNode[] };
  /** segments[p][i]: path p's ray from vertex i to vertex i + 1. */
  segments: RayNode[][];
  /** lights[p][i]: the light-sampling rays taken at vertex i of path p. */
  lights: RayNode[][][];
  /** vertices[p]: path p's vertices, as recorded. */
  vertices: PathVertex[][];
}

/** The throughput `carried` along each segment (what the debugger's rows say after each vertex), by path. */
export function pathTrees(paths: LabPaths, carried: readonly (readonly Color[])[]): PathTrees {
  const segments: RayNode[][] = [];
  const lights: RayNode[][][] = [];
  const roots: RayNode[] = [];
  paths.paths.forEach((path, p) => {
    const { vertices } = path;
    const pathSegments: RayNode[] = [];
    const pathLights: RayNode[][] = vertices.map(() => []);
    let parent: RayNode | null = null;
    for (let i = 0; i < vertices.length; i++) {
      const vertex = vertices[i];
      const width = Math.min(1, Math.max(...(carried[p]?.[i] ?? vertex.throughput)));
      for (const sample of vertex.lightSamples) {
        const ray = lightRay(vertex, sample.target, sample.visible, sample.lightId, sample.added, width);
        pathLights[i].push(ray);
        parent?.children.push(ray);
      }
      const next = vertices[i + 1];
      if (!next) break;
      const segment = segmentRay(vertex, next, i === 0 ? 'primary' : vertex.event === 'glass-refract' ? 'refract' : 'reflect', width);
      pathSegments.push(segment);
      if (parent) parent.children.push(segment);
      else roots.push(segment);
      parent = segment;
    }
    segments.push(pathSegments);
    lights.push(pathLights);
  });
  return { trace: { pixel: paths.pixel, color: paths.color, rays: roots }, segments, lights, vertices: paths.paths.map((path) => path.vertices) };
}

/**
 * What the 3D view shows with the cursor at vertex `vertex` of path `chosen`: every path up to
 * that vertex (its bounces so far and the light samples taken on the way), the chosen path
 * bright, the rest dimmed, and the chosen path's ray into that vertex highlighted and growing.
 * At a diffuse bounce, the distribution its next direction is drawn from (`sampling`, the
 * scene's bounceSampling) stands around the normal as a lobe.
 */
export function pathFocus(trees: PathTrees, chosen: number, vertex: number, sampling: BounceSampling = 'cosine'): RayFocus {
  const shown = new Set<RayNode>();
  const bright = new Set<RayNode>();
  trees.segments.forEach((segments, p) => {
    const rays = [...segments.slice(0, vertex), ...trees.lights[p].slice(0, vertex + 1).flat()];
    for (const ray of rays) {
      shown.add(ray);
      if (p === chosen) bright.add(ray);
    }
  });
  const highlighted = vertex > 0 ? (trees.segments[chosen]?.[vertex - 1] ?? null) : null;
  const at = trees.vertices[chosen]?.[vertex];
  const lobe = at?.event === 'diffuse' && at.normal ? { point: at.point, normal: at.normal, sampling, size: LOBE_SIZE } : null;
  return { trace: trees.trace, shown, highlighted, grow: highlighted !== null, bright, widthByContribution: true, paths: true, lobe };
}

/**
 * Every path whole, all bright, none highlighted: a chosen pixel's paths with the debugger
 * closed. They grow from the camera bounce by bounce as the ray panel's animation plays
 * (each ray starts where its parent ends, the light samples when their vertex is reached).
 */
export function allPathsFocus(trees: PathTrees): RayFocus {
  const shown = new Set([...trees.segments.flat(), ...trees.lights.flat(2)]);
  return { trace: trees.trace, shown, highlighted: null, grow: false, bright: shown, widthByContribution: true, paths: true, lobe: null, animated: true };
}

function segmentRay(from: PathVertex, to: PathVertex, type: RayType, width: number): RayNode {
  const origin = from.point;
  const length = Math.hypot(to.point[0] - origin[0], to.point[1] - origin[1], to.point[2] - origin[2]);
  return {
    type,
    origin,
    // From vertex to vertex: the tracer's ray starts ε off the surface, the drawing at the point.
    direction: unit(origin, to.point),
    length,
    hit: to.event !== 'escaped',
    objectId: to.objectId,
    lightId: to.lightId,
    color: [0, 0, 0],
    contribution: width,
    children: [],
  };
}

function lightRay(from: PathVertex, target: Color, visible: boolean, lightId: string, added: Color, width: number): RayNode {
  const origin = from.point;
  const length = Math.hypot(target[0] - origin[0], target[1] - origin[1], target[2] - origin[2]);
  return {
    type: visible ? 'light' : 'shadow',
    origin,
    direction: unit(origin, target),
    length,
    hit: true,
    objectId: null,
    lightId,
    color: added,
    contribution: width,
    children: [],
  };
}

function unit(from: Color, to: Color): Color {
  const d: Color = [to[0] - from[0], to[1] - from[1], to[2] - from[2]];
  const length = Math.hypot(...d) || 1;
  return [d[0] / length, d[1] / length, d[2] / length];
}
