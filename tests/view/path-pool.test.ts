import { describe, expect, it } from 'vitest';
import { type InstancedBufferAttribute, type InstancedMesh, type Mesh, Raycaster, Vector3 } from 'three';
import { DEFAULT_RAY_VIEW } from '../../src/lab-state/lab-state.ts';
import { PATH_DASHES } from '../../src/view/path-dashes.ts';
import { RAY_DASHES } from '../../src/view/ray-palette.ts';
import { RAY_CYLINDERS_NAME, RayPool } from '../../src/view/ray-pool.ts';
import { DASH_ATTRIBUTE } from '../../src/view/ray-shader.ts';
import type { RayFocus } from '../../src/view/ray-focus.ts';
import type { RayNode } from '../../src/tracer/ray-tree.ts';
import { ray } from '../support/ray-fixtures.ts';

/** A path of two segments from the camera, with a light sample (reached) and a blocked one at its first vertex. */
function pathFocus(paths: boolean): RayFocus {
  const light = ray('light', { origin: [0, 1, 1], direction: [0, 1, 0], length: 1 });
  const blocked = ray('shadow', { origin: [0, 1, 1], direction: [1, 0, 0], length: 0.5 });
  const bounce = ray('reflect', { origin: [0, 1, 1], direction: [0, 0, 1], length: 1 });
  const camera = ray('primary', { origin: [0, 1, 5], direction: [0, 0, -1], length: 4, children: [light, blocked, bounce] });
  const all = new Set<RayNode>([camera, light, blocked, bounce]);
  return {
    trace: { pixel: [2, 3], color: [0, 0, 0], rays: [camera] },
    shown: all,
    highlighted: null,
    grow: false,
    bright: all,
    paths,
    lobe: paths ? { point: [0, 1, 1], normal: [0, 0, 1], sampling: 'uniform', size: 0.4 } : null,
  };
}

function dashesOf(pool: RayPool): Map<string, number[]> {
  const cylinders = pool.object.getObjectByName(RAY_CYLINDERS_NAME) as InstancedMesh;
  const dash = cylinders.geometry.getAttribute(DASH_ATTRIBUTE) as InstancedBufferAttribute;
  const found = new Map<string, number[]>();
  for (let i = 0; i < cylinders.count; i++) found.set(String(i), [dash.getX(i), dash.getY(i)]);
  return found;
}

const fround = (pair: readonly number[]) => pair.map((value) => Math.fround(value));

describe('a pixel’s sample paths in the ray pool', () => {
  it('draws the bounces solid and the light-sampling rays dashed, reached or blocked', () => {
    const pool = new RayPool();
    pool.setFocus(pathFocus(true));
    pool.update(null, DEFAULT_RAY_VIEW, null);
    const drawn = [...dashesOf(pool).values()];
    // In tree order: camera ray, light sample, blocked sample, bounce (normals are solid too).
    expect(drawn).toContainEqual(fround(PATH_DASHES.light));
    expect(drawn).toContainEqual(fround([PATH_DASHES.shadow[0], -PATH_DASHES.shadow[1]]));
    expect(drawn.filter(([dash]) => dash === 0).length).toBeGreaterThanOrEqual(2);
    expect(drawn).not.toContainEqual(fround(RAY_DASHES.reflect));
    expect(PATH_DASHES.light[0]).toBeGreaterThan(0);
    expect(PATH_DASHES.reflect).toEqual([0, 0]);
  });

  it('keeps the usual patterns for the Whitted debugger, and the lobe only while asked for', () => {
    const pool = new RayPool();
    pool.setFocus(pathFocus(false));
    pool.update(null, DEFAULT_RAY_VIEW, null);
    const drawn = [...dashesOf(pool).values()];
    expect(drawn).toContainEqual(fround(RAY_DASHES.reflect));
    const lobes = () => pool.object.children.filter((child): child is Mesh => child.name === 'sampling-lobe');
    expect(lobes().length).toBe(2);
    expect(lobes().every((mesh) => !mesh.visible)).toBe(true);
    pool.setFocus(pathFocus(true));
    pool.update(null, DEFAULT_RAY_VIEW, null);
    expect(lobes().every((mesh) => mesh.visible)).toBe(true);
    // A uniform hemisphere of radius size/2 around the normal (+z here): every vertex half the size from the point.
    const [surface] = lobes();
    expect(surface!.position.toArray()).toEqual([0, 1, 1]);
    const position = surface!.geometry.getAttribute('position');
    for (let i = 0; i < position.count; i++) expect(Math.hypot(position.getX(i), position.getY(i), position.getZ(i))).toBeCloseTo(0.2, 5);
  });

  it('offers a click on a drawn path ray to the focus, with how far along the ray it landed', () => {
    const focus = pathFocus(true);
    const chosen: [RayNode, number][] = [];
    const pool = new RayPool();
    pool.setFocus({ ...focus, chooseRay: (node, at) => chosen.push([node, at]) > 0 });
    pool.update(null, DEFAULT_RAY_VIEW, null);
    // Straight down onto the camera ray (from z = 5 toward z = 1), 1 m before its end.
    const hover = pool.pick(new Raycaster(new Vector3(0, 5, 2), new Vector3(0, -1, 0)));
    const camera = focus.trace.rays[0]!;
    expect(hover?.node).toBe(camera);
    expect(hover?.at).toBeCloseTo(3, 2);
    // The tooltip names the focus's own pixel, and knows the ray is a path's.
    expect(hover).toMatchObject({ pixel: focus.trace.pixel, path: true });
    expect(pool.click(hover!)).toBe(true);
    expect(chosen).toEqual([[camera, hover!.at]]);
    // A focus that chooses nothing (the Whitted debugger's) leaves the click to the view.
    pool.setFocus(pathFocus(false));
    pool.update(null, DEFAULT_RAY_VIEW, null);
    expect(pool.click(hover!)).toBe(false);
  });
});
