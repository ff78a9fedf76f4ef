import { describe, expect, it } from 'vitest';
import { pathRows } from '../../src/debugger/path-steps.ts';
import { labPaths } from '../../src/tracer/lab-paths.ts';
import { allPathsFocus, pathFocus, pathTrees } from '../../src/view/path-focus.ts';
import { LOBE_SIZE } from '../../src/view/sampling-lobe.ts';
import { RAY_COLOR_KEY_INDEX } from '../../src/view/ray-palette.ts';
import { focusedRays } from '../../src/view/ray-focus.ts';
import { DEFAULT_RAY_VIEW } from '../../src/lab-state/lab-state.ts';
import { pathBallScene } from '../support/path-ball-scene.ts';

const scene = pathBallScene();
const paths = labPaths(scene, 2, 2, 1, 5);
const rows = paths.paths.map((path) => pathRows(path, { russianRoulette: false }));
const trees = pathTrees(
  paths,
  rows.map((r) => r.map((row) => row.throughput)),
);

describe('a pixel’s paths as ray trees for the 3D view', () => {
  it('has one tree per path, a ray per segment from vertex to vertex, a light or shadow ray per light sample', () => {
    expect(trees.trace.rays).toHaveLength(5);
    paths.paths.forEach((path, p) => {
      expect(trees.segments[p]).toHaveLength(path.vertices.length - 1);
      trees.segments[p]!.forEach((ray, i) => {
        expect(ray.origin).toEqual(path.vertices[i]!.point);
        const end = ray.origin.map((o, c) => o + ray.direction[c]! * ray.length);
        end.forEach((value, c) => expect(value).toBeCloseTo(path.vertices[i + 1]!.point[c]!, 9));
        expect(ray.type).toBe(i === 0 ? 'primary' : 'reflect');
      });
      path.vertices.forEach((vertex, i) => {
        expect(trees.lights[p]![i]!.map((ray) => ray.type)).toEqual(vertex.lightSamples.map((sample) => (sample.visible ? 'light' : 'shadow')));
      });
    });
    expect(trees.lights.flat(2).length).toBeGreaterThan(0);
  });

  it('shows every path up to the cursor’s vertex, the chosen path bright and its newest ray growing', () => {
    // A path that reaches its third vertex, whichever one the random numbers make it.
    const chosen = trees.segments.findIndex((segments) => segments.length >= 2);
    expect(chosen).toBeGreaterThanOrEqual(0);
    const focus = pathFocus(trees, chosen, 2);
    const expected = trees.segments.flatMap((segments, p) => [...segments.slice(0, 2), ...trees.lights[p]!.slice(0, 3).flat()]);
    expect([...focus.shown].sort()).toEqual(expected.sort());
    expect(focus.highlighted).toBe(trees.segments[chosen]![1]);
    expect(focus.grow).toBe(true);
    for (const ray of focus.bright ?? []) expect(trees.segments[chosen]!.includes(ray) || trees.lights[chosen]!.flat().includes(ray)).toBe(true);
    expect(focus.widthByContribution).toBe(true);
    // At the camera nothing has been cast yet.
    expect(pathFocus(trees, 0, 0).shown.size).toBe(0);
  });

  it('draws a segment as wide as the throughput it carries', () => {
    rows.forEach((r, p) => trees.segments[p]!.forEach((ray, i) => expect(ray.contribution).toBeCloseTo(Math.min(1, Math.max(...r[i]!.throughput)), 12)));
  });

  it('stands the sampling lobe at a diffuse vertex, by the scene’s strategy, and at no other', () => {
    let diffuse = 0;
    paths.paths.forEach((path, p) =>
      path.vertices.forEach((vertex, i) => {
        for (const sampling of ['cosine', 'uniform'] as const) {
          const lobe = pathFocus(trees, p, i, sampling).lobe;
          if (vertex.event !== 'diffuse') expect(lobe).toBeNull();
          else expect(lobe).toEqual({ point: vertex.point, normal: vertex.normal, sampling, size: LOBE_SIZE });
        }
        if (vertex.event === 'diffuse') diffuse++;
      }),
    );
    expect(diffuse).toBeGreaterThan(0);
    expect(pathFocus(trees, 0, 0).paths).toBe(true);
  });

  it('with the debugger closed, shows every path whole, growing from the camera bounce by bounce', () => {
    const focus = allPathsFocus(trees);
    expect(focus.shown.size).toBe(trees.segments.flat().length + trees.lights.flat(2).length);
    expect(focus.highlighted).toBeNull();
    expect(focus.animated).toBe(true);
    const drawn = focusedRays(focus, { ...DEFAULT_RAY_VIEW, animate: true });
    const startOf = new Map<unknown, number>();
    for (let i = 0; i < drawn.rays.count; i++) if (drawn.rays.colorKey[i] !== RAY_COLOR_KEY_INDEX.normal) startOf.set(drawn.rays.nodes[i], drawn.rays.start[i]);
    // Each bounce starts to grow where the one before it has arrived.
    trees.segments.forEach((segments) =>
      segments.slice(1).forEach((ray, i) => expect(startOf.get(ray)).toBeCloseTo(startOf.get(segments[i])! + segments[i]!.length, 4)),
    );
    expect(drawn.travelEnd).toBeGreaterThan(Math.max(...trees.segments.map((segments) => segments[0]!.length)));
  });
});
