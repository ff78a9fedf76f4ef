import { describe, expect, it } from 'vitest';
import { createLight, createObject, defaultScene } from '../../src/scene/scene-defaults.ts';
import { parseScene } from '../../src/scene/scene-schema.ts';
import type { LightType, ShapeKind } from '../../src/scene/scene.ts';

const SHAPES: ShapeKind[] = ['sphere', 'box', 'cylinder', 'plane', 'mesh'];
const LIGHT_TYPES: LightType[] = ['point', 'spot', 'area'];

describe('defaultScene', () => {
  it('is a valid scene file as it stands', () => {
    const scene = defaultScene();
    expect(parseScene(scene)).toEqual({ ok: true, scene });
  });

  it('has the spec’s screen and image sizes, a floor, three spheres, a box and lights', () => {
    const scene = defaultScene();
    expect(scene.camera.pixels).toEqual([8, 6]);
    expect(scene.settings.imageSize).toEqual([512, 384]);
    expect(scene.objects.map((object) => object.shape)).toEqual(['plane', 'sphere', 'sphere', 'sphere', 'box']);
    expect(scene.objects[0]!.scale).toEqual([10, 1, 10]);
    expect(scene.objects.some((object) => object.material.transparent)).toBe(true);
    expect(scene.lights.map((light) => light.type)).toEqual(['point', 'spot']);
  });

  it('is a fresh copy every time', () => {
    const first = defaultScene();
    first.objects[1]!.position[0] = 99;
    expect(defaultScene().objects[1]!.position[0]).not.toBe(99);
  });
});

describe('createObject and createLight', () => {
  it.each(SHAPES)('create a valid %s', (shape) => {
    const scene = defaultScene();
    scene.objects.push(createObject(shape, scene));
    expect(parseScene(scene).ok).toBe(true);
  });

  it.each(LIGHT_TYPES)('create a valid %s light', (type) => {
    const scene = defaultScene();
    scene.lights.push(createLight(type, scene));
    expect(parseScene(scene).ok).toBe(true);
  });

  it('gives a mesh object a model and other shapes none', () => {
    const scene = defaultScene();
    expect(createObject('mesh', scene).mesh).toBe('prism');
    expect('mesh' in createObject('sphere', scene)).toBe(false);
  });

  it('numbers ids past those already used by objects and lights', () => {
    const scene = defaultScene();
    const ids = [];
    for (let count = 0; count < 3; count++) {
      const box = createObject('box', scene);
      scene.objects.push(box);
      ids.push(box.id);
    }
    scene.objects.push({ ...createObject('sphere', scene), id: 'spot-1' });
    expect(ids).toEqual(['box-1', 'box-2', 'box-3']);
    expect(createLight('spot', scene).id).toBe('spot-2');
  });

  it('names a new object or light in both languages, with the number of its id', () => {
    const scene = defaultScene();
    expect(createObject('sphere', scene).name).toEqual({ en: 'Sphere 1', nl: 'Bol 1' });
    scene.lights.push(createLight('area', scene));
    expect(createLight('area', scene)).toMatchObject({ id: 'area-2', name: { en: 'Area light 2', nl: 'Vlaklamp 2' } });
  });
});
