import { describe, expect, it } from 'vitest';
import type { Material } from '../../src/scene/scene.ts';
import { tracerMaterial } from '../../src/tracer/tracer-material.ts';

describe('tracerMaterial', () => {
  it('copies every field of the material, its colour into an array of its own', () => {
    const glass: Material = {
      color: [1, 0.5, 0],
      ambient: 0,
      diffuse: 0.1,
      specular: 0.5,
      shininess: 300,
      transparent: true,
      refractiveIndex: 1.5,
      roughness: 0.2,
      glossySamples: 3,
    };
    const copy = tracerMaterial(glass);

    expect(copy).toEqual(glass);
    expect(Object.keys(copy)).toEqual(Object.keys(glass));
    glass.color[0] = 0;
    expect(copy.color).toEqual([1, 0.5, 0]);
  });
});
