import { describe, expect, it } from 'vitest';
import { pathRows } from '../../src/debugger/path-steps.ts';
import { labPaths } from '../../src/tracer/lab-paths.ts';
import { pathTrees } from '../../src/view/path-focus.ts';
import { pathVertexOfRay } from '../../src/view/path-vertex-pick.ts';
import { ray } from '../support/ray-fixtures.ts';
import { matte, tracerSceneFrom } from '../support/test-scene.ts';

const scene = tracerSceneFrom({
  camera: { position: [0, 1, 3.5], target: [0, 0.5, 0], fov: 45, pixels: [4, 4] },
  settings: { integrator: 'path', background: [0.2, 0.2, 0.2], maxDepth: 4, pathSamples: 16 },
  objects: [
    { id: 'floor', shape: 'plane', scale: [3, 1, 3], material: matte([0.7, 0.7, 0.7]) },
    { id: 'ball', shape: 'sphere', position: [0, 0.5, 0], scale: [0.5, 0.5, 0.5], material: matte([0.8, 0.3, 0.3]) },
  ],
  lights: [{ id: 'panel', type: 'area', position: [0, 2, 0], size: [0.5, 0.5], color: [1, 1, 1], intensity: 5, samples: 1 }],
});
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
