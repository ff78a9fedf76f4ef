/**
 * The object-count scenes of the benchmark: side × side objects (spheres, boxes and
 * cylinders in turn, every fifth a mirror) on a square grid of fixed size, each object
 * scaled to its cell, lit like the reference scene. The grid covers the same part of the
 * image whatever the count, so 3 × 3 = 9 and 16 × 16 = 256 objects (the scene limit) take
 * about the same number of rays: their time ratio is the cost of the object count itself.
 */
import { issueLine } from '../src/util/issue.ts';
import type { Scene } from '../src/scene/scene.ts';
import { parseScene } from '../src/scene/scene-schema.ts';

const GRID_SIZE = 6;
const KINDS = ['sphere', 'box', 'cylinder'] as const;

export function objectGridScene(side: number): Scene {
  const cell = GRID_SIZE / side;
  const size = cell * 0.7;
  const objects = Array.from({ length: side * side }, (_, i) => {
    const column = i % side;
    const row = Math.floor(i / side);
    const mirror = i % 5 === 4;
    return {
      id: `object-${i}`,
      shape: KINDS[i % KINDS.length],
      position: [(column + 0.5) * cell - GRID_SIZE / 2, size / 2, (row + 0.5) * cell - GRID_SIZE / 2],
      rotation: [0, (i * 37) % 90, 0],
      scale: [size, size, size],
      material: mirror
        ? { color: [0.1, 0.1, 0.1], ambient: 0, diffuse: 0.1, specular: 0.9, shininess: 200 }
        : { color: [0.3 + 0.6 * (column / side), 0.4, 0.3 + 0.6 * (row / side)], ambient: 0.1, diffuse: 0.9, specular: 0.3, shininess: 32 },
    };
  });
  const parsed = parseScene({
    version: 1,
    name: `Benchmark grid of ${side * side} objects`,
    camera: { position: [0, 5.5, 6], target: [0, 0, 0], fov: 50 },
    settings: { shadows: true, maxDepth: 3, background: [0.55, 0.65, 0.8], supersampling: 2, imageSize: [256, 256] },
    objects,
    lights: [
      { id: 'panel', type: 'area', position: [-1, 3.6, 1], size: [1.4, 1.4], samples: 4, color: [1, 1, 1], intensity: 0.8, ambient: 0.05, angleAttenuation: 0 },
      { id: 'bulb', type: 'point', position: [3, 4, 3], color: [1, 0.95, 0.85], intensity: 0.5, ambient: 0.05 },
    ],
  });
  if (!parsed.ok) throw new Error(`the ${side}×${side} grid scene is invalid:\n${parsed.errors.map(issueLine).join('\n')}`);
  return parsed.scene;
}
