import { describe, expect, it } from 'vitest';
import { findPathVertex, pathRayOf } from '../../src/debugger/path-goals.ts';
import { labPaths } from '../../src/tracer/lab-paths.ts';
import { pathBallScene } from '../support/path-ball-scene.ts';

const scene = pathBallScene();

describe('the path debugger’s steps as the quest engine sees them', () => {
  it('reports no ray at the camera, then the ray that arrived at each vertex', () => {
    const paths = labPaths(scene, 2, 2, 1, 16).paths;
    for (const path of paths) {
      expect(pathRayOf(path, 0)).toBeNull();
      for (let i = 1; i < path.vertices.length; i++) {
        const ray = pathRayOf(path, i)!;
        const at = path.vertices[i]!;
        expect(ray.type).toBe(i === 1 ? 'primary' : 'reflect');
        expect(ray.depth).toBe(i - 1);
        expect(ray.objectId).toBe(at.objectId);
        expect(ray.hit).toBe(at.event !== 'escaped');
        expect(ray.from).toBe(path.vertices[i - 1]!.objectId);
      }
      expect(pathRayOf(path, path.vertices.length)).toBeNull();
    }
    // The pixel looks at the ball: its first ray arrives there from the camera.
    expect(paths.some((path) => pathRayOf(path, 1)?.objectId === 'ball')).toBe(true);
  });

  it('finds where "show me" takes a path-debugger step: the solution’s ray, else the first of its kind', () => {
    const paths = labPaths(scene, 2, 2, 1, 16).paths;
    expect(findPathVertex(paths, null)).toEqual({ path: 0, vertex: 0 });
    // Every vertex's own ray leads back to the first vertex with that very ray.
    paths.forEach((path, p) =>
      path.vertices.forEach((_, v) => {
        const ray = pathRayOf(path, v);
        if (!ray) return;
        const found = findPathVertex(paths, ray)!;
        expect(pathRayOf(paths[found.path]!, found.vertex)).toEqual(ray);
        expect(found.path * 100 + found.vertex).toBeLessThanOrEqual(p * 100 + v);
      }),
    );
    // A second bounce off an object this scene does not have: the first second bounce instead.
    const deep = findPathVertex(paths, { type: 'reflect', depth: 1, objectId: 'no-such-wall' });
    expect(deep).not.toBeNull();
    expect(pathRayOf(paths[deep!.path]!, deep!.vertex)?.type).toBe('reflect');
    expect(findPathVertex(paths, { type: 'refract' })).toBeNull();
    expect(findPathVertex([], null)).toBeNull();
  });
});
