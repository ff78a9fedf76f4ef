import { describe, expect, it } from 'vitest';
import { pathRows } from '../../src/debugger/path-steps.ts';
import { labPaths } from '../../src/tracer/lab-paths.ts';
import { pathTrees } from '../../src/view/path-focus.ts';
import { pathVertexOfRay } from '../../src/view/path-vertex-pick.ts';
import { ray } from '../support/ray-fixtures.ts';
import { pathBallScene } from '../support/path-ball-scene.ts';

const scene = pathBallScene();
const paths = labPaths(scene, 2, 2, 1, 5);
const trees = pathTrees(
  paths,
  paths.paths.map((path) => pathRows(path, { russianRoulette: false }).map((row) => row.throughput)),
);

describe('choosing a path vertex by clicking its drawn rays', () => {
  it('takes the nearer end of a clicked segment, in the path it belongs to', () => {
    trees.segments.forEach((segments, path) =>
      segments.forEach((segment, i) => {
        expect(pathVertexOfRay(trees, segment, segment.length * 0.2)).toEqual({ path, vertex: i });
        expect(pathVertexOfRay(trees, segment, segment.length * 0.8)).toEqual({ path, vertex: i + 1 });
      }),
    );
    expect(trees.segments.flat().length).toBeGreaterThan(5);
  });

  it('gives a light-sampling ray the vertex it was taken at, and no vertex for other rays', () => {
    let checked = 0;
    trees.lights.forEach((vertices, path) =>
      vertices.forEach((rays, vertex) =>
        rays.forEach((light) => {
          expect(pathVertexOfRay(trees, light, light.length)).toEqual({ path, vertex });
          checked++;
        }),
      ),
    );
    expect(checked).toBeGreaterThan(0);
    expect(pathVertexOfRay(trees, ray('primary', { origin: [0, 0, 0], direction: [0, 0, -1], length: 1 }), 0)).toBeNull();
  });
});
