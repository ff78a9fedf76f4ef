import { describe, expect, it } from 'vitest';
import { followRayPath, RAY_PATH_PATTERN } from '../../src/tracer/ray-path.ts';
import type { PixelTrace } from '../../src/tracer/ray-tree.ts';
import { ray } from '../support/ray-fixtures.ts';

/** A glass pixel: the camera's ray, a shadow ray, a reflection to a light, and a refraction that reflects inside. */
const inside = ray('reflect', { objectId: 'block' });
const trace: PixelTrace = {
  pixel: [4, 2],
  color: [0.5, 0.5, 0.5],
  rays: [
    ray('primary', {
      objectId: 'block',
      children: [
        ray('shadow', { objectId: 'ball' }),
        ray('reflect', { objectId: 'wall', children: [ray('light')] }),
        ray('refract', { objectId: 'block', children: [inside] }),
      ],
    }),
  ],
};

describe('a ray path', () => {
  it('names a ray by the kinds on the way to it from the camera, each the first child of its kind', () => {
    expect(followRayPath(trace, 'primary')).toBe(trace.rays[0]);
    expect(followRayPath(trace, 'primary/shadow')?.objectId).toBe('ball');
    expect(followRayPath(trace, 'primary/reflect/light')?.type).toBe('light');
    expect(followRayPath(trace, 'primary/refract/reflect')).toBe(inside);
  });

  it('finds nothing where the tree has no such ray', () => {
    expect(followRayPath(trace, 'primary/refract/refract')).toBeNull();
    expect(followRayPath(trace, 'primary/light')).toBeNull();
    expect(followRayPath({ ...trace, rays: [] }, 'primary')).toBeNull();
  });

  it('is written from "primary", with a "/" before each further kind', () => {
    for (const path of ['primary', 'primary/shadow', 'primary/primary/refract/area-light']) expect(path).toMatch(RAY_PATH_PATTERN);
    for (const path of ['shadow', 'primary/', 'primary//reflect', 'primary/bounce', 'primary > reflect']) expect(path).not.toMatch(RAY_PATH_PATTERN);
  });
});
