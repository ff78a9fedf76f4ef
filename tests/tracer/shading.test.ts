import { Vector3 } from 'three';
import { describe, expect, it } from 'vitest';
import { distanceAttenuation } from '../../src/tracer/attenuation.ts';
import { Ray } from '../../src/tracer/ray.ts';
import { RayRecorder } from '../../src/tracer/ray-recorder.ts';
import type { RayNode } from '../../src/tracer/ray-tree.ts';
import { integratorFor } from '../../src/tracer/render-pixel.ts';
import type { TracerScene } from '../../src/tracer/tracer-scene.ts';
import { matte, pointLight, tracerSceneFrom } from '../support/test-scene.ts';

const BLACK = [0, 0, 0];
const floor = (material: Record<string, unknown>) => ({ id: 'floor', shape: 'plane', scale: [20, 1, 20], material });

/** The colour seen by one ray from `from` toward `to`. */
function colorAlong(scene: TracerScene, from: number[], to: number[], node: RayNode | null = null): number[] {
  const origin = new Vector3(...from);
  const direction = new Vector3(...to).sub(origin).normalize();
  return integratorFor(scene)
    .li(new Ray().set(origin, direction), new Vector3(), node ? new RayRecorder(node) : null)
    .toArray();
}

function rootNode(): RayNode {
  return {
    type: 'primary',
    origin: [0, 0, 0],
    direction: [0, 0, 1],
    length: 0,
    hit: false,
    objectId: null,
    lightId: null,
    color: [0, 0, 0],
    contribution: 0,
    children: [],
  };
}

function expectColor(actual: number[], expected: number[]): void {
  actual.forEach((c, i) => expect(c).toBeCloseTo(expected[i], 10));
}

describe('Phong shading (spec §2)', () => {
  it('Lambert: diffuse = max(N·L, 0)·kd·ld·Lc·C', () => {
    const scene = tracerSceneFrom({
      settings: { background: BLACK },
      objects: [floor(matte([0.5, 0.25, 1], { diffuse: 0.8 }))],
      lights: [pointLight([2, 4, 0], { diffuse: 0.9, color: [1, 0.5, 1] })],
    });
    const nDotL = 4 / Math.sqrt(20);
    expectColor(colorAlong(scene, [0, 3, 3], [0, 0, 0]), [0.5 * nDotL * 0.8 * 0.9, 0.25 * nDotL * 0.8 * 0.9 * 0.5, Math.min(1, nDotL * 0.8 * 0.9)]);
  });

  it('ambient: ka·C plus la·Lc·C for each light, even in shadow', () => {
    const scene = tracerSceneFrom({
      settings: { background: BLACK },
      objects: [floor(matte([0.5, 0.5, 0.5], { ambient: 0.2, diffuse: 0 }))],
      lights: [pointLight([0, -4, 0], { ambient: 0.3, color: [1, 0, 1] })],
    });
    expectColor(colorAlong(scene, [0, 3, 3], [0, 0, 0]), [0.5 * 0.2 + 0.3 * 0.5, 0.5 * 0.2, 0.5 * 0.2 + 0.3 * 0.5]);
  });

  it('Phong highlight: max(R·V, 0)^n·ks·ls·Lc, untinted by the object colour', () => {
    const lights = [pointLight([0, 3, -3], { specular: 0.8 })];
    const material = matte([0.2, 0, 0], { specular: 0.5, shininess: 10 });
    const scene = tracerSceneFrom({ settings: { background: BLACK }, objects: [floor(material)], lights });
    const diffuse = 3 / Math.sqrt(18);
    // Viewer exactly on the mirror direction: R·V = 1.
    expectColor(colorAlong(scene, [0, 3, 3], [0, 0, 0]), [0.2 * diffuse + 0.5 * 0.8, 0.5 * 0.8, 0.5 * 0.8]);
    // Off the mirror direction the highlight falls off as cos^n.
    const v = new Vector3(0, 3, 4).normalize();
    const l = new Vector3(0, 3, -3).normalize();
    const r = new Vector3(0, 1, 0).multiplyScalar(2 * l.y).sub(l);
    const highlight = Math.pow(r.dot(v), 10) * 0.5 * 0.8;
    expectColor(colorAlong(scene, [0, 3, 4], [0, 0, 0]), [0.2 * diffuse + highlight, highlight, highlight]);
  });

  it('distance attenuation scales the diffuse and specular terms', () => {
    const scene = tracerSceneFrom({
      settings: { background: BLACK },
      objects: [floor(matte([1, 1, 1], { diffuse: 0.1 }))],
      lights: [pointLight([0, 3, 0], { distanceAttenuation: true })],
    });
    expectColor(colorAlong(scene, [1, 3, 3], [0, 0, 0]), Array(3).fill(0.1 * distanceAttenuation(3)));
  });

  it('a spot light lights inside its cone and nothing outside it', () => {
    const spot = {
      id: 'spot',
      type: 'spot',
      position: [0, 2, 0],
      rotation: [0, 0, 0],
      spotAngle: 60,
      angleAttenuation: 0,
      color: [1, 1, 1],
      intensity: 1,
      ambient: 0,
      diffuse: 1,
      specular: 0,
      distanceAttenuation: false,
    };
    const scene = tracerSceneFrom({ settings: { background: BLACK }, objects: [floor(matte([1, 1, 1]))], lights: [spot] });
    const edge = (degrees: number) => 2 * Math.tan((degrees * Math.PI) / 180);
    const inside = colorAlong(scene, [edge(29.9), 1, 0], [edge(29.9), 0, 0]);
    const outside = colorAlong(scene, [edge(30.1), 1, 0], [edge(30.1), 0, 0]);
    expect(inside[0]).toBeCloseTo(Math.cos((29.9 * Math.PI) / 180), 10);
    expect(outside).toEqual([0, 0, 0]);
  });

  it('shadows: an object between the point and the light blocks it; switched off, it does not', () => {
    const objects = [floor(matte([1, 1, 1])), { id: 'blocker', shape: 'box', position: [0, 1, 0], scale: [0.2, 0.2, 0.2], material: matte([1, 1, 1]) }];
    const lights = [pointLight([0, 3, 0])];
    const withShadows = tracerSceneFrom({ settings: { background: BLACK }, objects, lights });
    const without = tracerSceneFrom({ settings: { background: BLACK, shadows: false }, objects, lights });
    expect(colorAlong(withShadows, [0.01, 0.5, 0], [0.01, 0, 0])).toEqual([0, 0, 0]);
    expect(colorAlong(without, [0.01, 0.5, 0], [0.01, 0, 0])[0]).toBeGreaterThan(0.99);
  });
});

describe('area lights (spec §2)', () => {
  const area = (extra: Record<string, unknown>) => ({
    id: 'panel',
    type: 'area',
    position: [0, 2, 0],
    rotation: [0, 0, 0],
    size: [1, 1],
    samples: 4,
    angleAttenuation: 0,
    shape: 'rectangle',
    color: [1, 1, 1],
    intensity: 1,
    ambient: 0,
    diffuse: 1,
    specular: 0,
    distanceAttenuation: false,
    ...extra,
  });

  it('with every sample visible, the shadowed result equals the unshadowed one, and lies within the N·L bounds', () => {
    const make = (shadows: boolean) => tracerSceneFrom({ settings: { background: BLACK, shadows }, objects: [floor(matte([1, 1, 1]))], lights: [area({})] });
    const lit = colorAlong(make(true), [0, 1, 0.001], [0, 0, 0]);
    expect(lit).toEqual(colorAlong(make(false), [0, 1, 0.001], [0, 0, 0]));
    const cosCorner = 2 / Math.sqrt(4 + 0.5);
    expect(lit[0]).toBeGreaterThan(cosCorner ** 2);
    expect(lit[0]).toBeLessThanOrEqual(1);
  });

  it('a tiny area light behaves like a spot light at its centre (N·L · cos α), a disc too', () => {
    for (const shape of ['rectangle', 'disc']) {
      const scene = tracerSceneFrom({
        settings: { background: BLACK },
        objects: [floor(matte([1, 1, 1]))],
        lights: [area({ size: [0.01, 0.01], shape, angleAttenuation: 1 })],
      });
      const nDotL = 2 / Math.sqrt(4 + 1);
      expect(colorAlong(scene, [1, 1, 0.001], [1, 0, 0])[0]).toBeCloseTo(nDotL * nDotL, 2);
    }
  });

  it('a small occluder gives a penumbra: some samples blocked, some not', () => {
    const blocker = { id: 'blocker', shape: 'box', position: [0.3, 1, 0], scale: [0.5, 0.05, 2], material: matte([1, 1, 1]) };
    const scene = tracerSceneFrom({ settings: { background: BLACK }, objects: [floor(matte([1, 1, 1])), blocker], lights: [area({})] });
    const open = tracerSceneFrom({ settings: { background: BLACK }, objects: [floor(matte([1, 1, 1]))], lights: [area({})] });
    const partial = colorAlong(scene, [0.1, 0.5, 0.001], [0.1, 0, 0])[0];
    expect(partial).toBeGreaterThan(0.1);
    expect(partial).toBeLessThan(colorAlong(open, [0.1, 0.5, 0.001], [0.1, 0, 0])[0] - 0.1);
  });

  it('the back face of an area light is black', () => {
    const scene = tracerSceneFrom({ settings: { background: BLACK }, objects: [floor(matte([1, 1, 1]))], lights: [area({ position: [0, -1, 0] })] });
    // The light is below the floor and faces down: the floor's underside gets nothing from above it.
    expect(colorAlong(scene, [0, -3, 0.001], [0, 0, 0])).toEqual([0, 0, 0]);
  });
});

describe('reflection and refraction (spec §2)', () => {
  it('a mirror adds ks × the colour seen along the reflected ray', () => {
    const mirror = matte([0, 0, 0], { diffuse: 0, specular: 0.7, shininess: 1000 });
    const ball = { id: 'ball', shape: 'sphere', position: [0, 2, -2], material: matte([1, 0.2, 0.1], { ambient: 1, diffuse: 0 }) };
    const scene = tracerSceneFrom({ settings: { background: BLACK }, objects: [floor(mirror), ball], lights: [] });
    const seenInMirror = colorAlong(scene, [0, 2, 2], [0, 0, 0]);
    const seenDirectly = colorAlong(scene, [0, 0.0001, 0], [0, 2, -2]);
    expectColor(
      seenInMirror,
      seenDirectly.map((c) => 0.7 * c),
    );
  });

  it('recursion stops at maxDepth: a mirror at depth 0 shows the background', () => {
    const mirror = matte([0, 0, 0], { diffuse: 0, specular: 1 });
    const scene = tracerSceneFrom({ settings: { background: [0, 0, 1], maxDepth: 0 }, objects: [floor(mirror)], lights: [] });
    expect(colorAlong(scene, [0, 2, 2], [0, 0, 0])).toEqual([0, 0, 0]);
  });

  it('glass splits into Schlick-weighted reflect and refract rays; TIR reflects only', () => {
    const glass = { id: 'glass', shape: 'sphere', material: matte([1, 1, 1], { transparent: true, diffuse: 0 }) };
    const scene = tracerSceneFrom({ settings: { background: [1, 1, 1] }, objects: [glass], lights: [] });
    const outside = rootNode();
    colorAlong(scene, [0, 0, 3], [0, 0, 0], outside);
    expect(outside.children.map((c) => c.type)).toEqual(['refract', 'reflect']);
    // From inside, at 64° from the normal (critical angle 41.8°): total internal reflection.
    const inside = rootNode();
    colorAlong(scene, [0, 0.45, 0], [1, 0.45, 0], inside);
    expect(inside.children.map((c) => c.type)).toEqual(['reflect']);
  });
});
