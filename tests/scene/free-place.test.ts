import { describe, expect, it } from 'vitest';
import { footprintRadius, freePlace } from '../../src/scene/free-place.ts';
import { createObject, defaultScene } from '../../src/scene/scene-defaults.ts';
import type { Scene, SceneObject } from '../../src/scene/scene.ts';

/** Whether two objects' footprints on the floor overlap. */
const overlap = (a: SceneObject, b: SceneObject) =>
  Math.hypot(a.position[0] - b.position[0], a.position[2] - b.position[2]) < footprintRadius(a) + footprintRadius(b);

describe('freePlace', () => {
  it('is where the camera looks when nothing stands there', () => {
    const scene = defaultScene();
    expect(freePlace([], 0.5, [1, 0, -2])).toEqual([1, -2]);
    expect(
      freePlace(
        scene.objects.filter((o) => o.shape === 'plane'),
        0.5,
        [0, 0.5, 0],
      ),
    ).toEqual([0, 0]);
  });

  it('is the nearest grid point clear of every standing object', () => {
    const ball = createObject('sphere', { ...defaultScene(), objects: [] });
    ball.position = [0, 0.5, 0];
    const [x, z] = freePlace([ball], footprintRadius(ball), [0, 0, 0]);
    const distance = Math.hypot(x, z);
    expect(distance).toBeGreaterThanOrEqual(2 * footprintRadius(ball));
    expect(distance).toBeLessThan(2 * footprintRadius(ball) + 0.5);
  });
});

describe('a new object', () => {
  /** The sandbox's scene: a floor and a ball at the centre, where new objects used to appear inside it. */
  const sandbox = (): Scene => {
    const scene = defaultScene();
    const ball = { ...scene.objects[1]!, id: 'ball', position: [0, 0.5, 0] as [number, number, number] };
    return { ...scene, objects: [scene.objects[0]!, ball], camera: { ...scene.camera, target: [0, 0.5, 0] } };
  };

  it.each(['sphere', 'box', 'cylinder', 'mesh'] as const)('a %s stands on the floor, inside nothing', (shape) => {
    const scene = sandbox();
    for (let count = 0; count < 4; count++) {
      const object = createObject(shape, scene);
      expect(object.position[1]).toBeCloseTo(0.5 * object.scale[1]);
      for (const other of scene.objects.filter((o) => o.shape !== 'plane')) expect(overlap(object, other), `${object.id} and ${other.id}`).toBe(false);
      scene.objects.push(object);
    }
  });

  it('a wine glass is clear glass, other models are not', () => {
    const glass = createObject('mesh', sandbox(), 'wine-glass');
    expect(glass.mesh).toBe('wine-glass');
    expect(glass.material).toMatchObject({ transparent: true, refractiveIndex: 1.5 });
    expect(glass.material).toEqual(defaultScene().objects.find((o) => o.id === 'glass-ball')!.material);
    expect(createObject('mesh', sandbox(), 'capsule').material.transparent).toBe(false);
  });
});
