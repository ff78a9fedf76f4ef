/** Hand-made ray trees for the ray view's tests and benchmark. */
import type { ScreenRays } from '../../src/render/screen-rays.ts';
import type { Vec3 } from '../../src/scene/scene.ts';
import type { PixelTrace, RayNode, RayType } from '../../src/tracer/ray-tree.ts';

export function ray(type: RayType, fields: Partial<RayNode> = {}): RayNode {
  return {
    type,
    origin: [0, 0, 0],
    direction: [0, 0, -1],
    length: 2,
    hit: true,
    objectId: null,
    lightId: null,
    color: [0.5, 0.5, 0.5],
    contribution: 1,
    children: [],
    ...fields,
  };
}

/** A merged area-light node toward a 2 × 1 m light centred 3 m above the origin. */
export function areaRay(type: 'area-light' | 'area-shadow', fields: Partial<RayNode> = {}): RayNode {
  const corners: [Vec3, Vec3, Vec3, Vec3] = [
    [-1, 3, -0.5],
    [1, 3, -0.5],
    [1, 3, 0.5],
    [-1, 3, 0.5],
  ];
  return ray(type, { direction: [0, 1, 0], length: 3, corners, ...fields });
}

/** A screen of `columns × rows` pixels, each with the trees `rootsFor(x, y)` returns. */
export function screen(columns: number, rows: number, rootsFor: (x: number, y: number) => RayNode[]): ScreenRays {
  const traces: PixelTrace[] = [];
  for (let y = 0; y < rows; y++) {
    for (let x = 0; x < columns; x++) traces.push({ pixel: [x, y], color: [0.2, 0.3, 0.4], rays: rootsFor(x, y) });
  }
  return { columns, rows, traces };
}

/** Counts every node of the trees. */
export function countNodes(roots: readonly RayNode[]): number {
  return roots.reduce((sum, node) => sum + 1 + countNodes(node.children), 0);
}

/**
 * A screen with about `total` rays in realistic trees: per pixel a primary ray that hits,
 * a light and a shadow ray from its hit, and a reflection with one light ray (5 rays).
 */
export function syntheticScreen(total: number): ScreenRays {
  const pixels = Math.ceil(total / 5);
  const columns = Math.ceil(Math.sqrt(pixels));
  const rows = Math.ceil(pixels / columns);
  let made = 0;
  return screen(columns, rows, (x, y) => {
    if (made >= pixels) return [];
    made++;
    const direction: Vec3 = [(x / columns - 0.5) * 0.8, (0.5 - y / rows) * 0.6, -1];
    const n = Math.hypot(...direction);
    const unit = direction.map((c) => c / n) as Vec3;
    const hitPoint = unit.map((c, axis) => [0, 1, 5][axis] + c * 5) as Vec3;
    return [
      ray('primary', {
        origin: [0, 1, 5],
        direction: unit,
        length: 5,
        contribution: 1,
        children: [
          ray('light', { origin: hitPoint, direction: [0, 1, 0], length: 3, contribution: 0.5 }),
          ray('shadow', { origin: hitPoint, direction: [0.6, 0.8, 0], length: 1, contribution: 0, color: [0, 0, 0] }),
          ray('reflect', {
            origin: hitPoint,
            direction: [unit[0], -unit[1], unit[2]],
            length: 4,
            contribution: 0.3,
            children: [ray('light', { origin: hitPoint, direction: [0, 1, 0], length: 2, contribution: 0.1 })],
          }),
        ],
      }),
    ];
  });
}

/** Visits every node of the trees, parents before children. */
export function walkRays(nodes: readonly RayNode[], visit: (node: RayNode) => void): void {
  for (const node of nodes) {
    visit(node);
    walkRays(node.children, visit);
  }
}
