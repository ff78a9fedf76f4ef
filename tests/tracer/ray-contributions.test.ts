import { describe, expect, it } from 'vitest';
import { assignContributions } from '../../src/tracer/ray-contributions.ts';
import type { RayNode } from '../../src/tracer/ray-tree.ts';
import { tracePixel } from '../../src/tracer/trace-pixel.ts';
import { matte, pointLight, tracerSceneFrom } from '../support/test-scene.ts';

function node(type: RayNode['type'], color: [number, number, number], children: RayNode[] = []): RayNode {
  return { type, origin: [0, 0, 0], direction: [0, 0, 1], length: 1, hit: true, objectId: null, lightId: null, color, contribution: 0, children };
}

/** Every node whose children's shares add up to more than its own, as "type: parent → children". */
function overShared(nodes: RayNode[], out: string[] = []): string[] {
  for (const n of nodes) {
    const children = n.children.reduce((total, child) => total + child.contribution, 0);
    if (children > n.contribution * (1 + 1e-12)) out.push(`${n.type}: ${n.contribution} → ${children}`);
    overShared(n.children, out);
  }
  return out;
}

describe('the shares of a hit brighter than white (clamped to 1)', () => {
  it("divide by the hit's unclamped colour: lights adding 0.8 and 0.4 to a hit clamped from 1.2 to 1 get 2/3 and 1/3", () => {
    const strong = node('light', [0.8, 0.8, 0.8]);
    const weak = node('light', [0.4, 0.4, 0.4]);
    const hit = node('primary', [1, 1, 1], [strong, weak]);
    assignContributions([hit], new Map(), new Map([[hit, 1.2 * 3]]));
    expect(strong.contribution + weak.contribution).toBeCloseTo(1, 12);
    expect(strong.contribution).toBeCloseTo(2 / 3, 12);
  });

  it("never add up to more than their parent's in a traced tree with bright lights and a mirror", () => {
    const scene = tracerSceneFrom({
      settings: { supersampling: 2 },
      objects: [
        { id: 'floor', shape: 'plane', scale: [10, 1, 10], material: matte([1, 1, 1], { ambient: 0.2, specular: 0.6 }) },
        { id: 'ball', shape: 'sphere', position: [0, 0.5, 0], material: matte([1, 0.9, 0.8], { specular: 0.8 }) },
      ],
      lights: [pointLight([1, 3, 2], { intensity: 2 }), pointLight([-2, 2, 1], { id: 'second', intensity: 2 })],
    });
    const [columns, rows] = scene.source.camera.pixels;
    let clamped = 0;
    for (let y = 0; y < rows; y++) {
      for (let x = 0; x < columns; x++) {
        const trace = tracePixel(scene, x, y, 0);
        expect(overShared(trace.rays)).toEqual([]);
        clamped += trace.rays.filter((root) => root.color.some((c) => c === 1)).length;
      }
    }
    // The scene does have hits that the clamp cuts (else the test would prove nothing).
    expect(clamped).toBeGreaterThan(0);
  });
});
