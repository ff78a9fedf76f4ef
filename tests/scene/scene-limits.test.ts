import { describe, expect, it } from 'vitest';
import { parseScene, type SceneParseResult } from '../../src/scene/scene-schema.ts';
import { issueLine } from '../../src/util/issue.ts';

/** A result with its problems as the English lines `rt validate` prints. */
function inLines(result: SceneParseResult) {
  return result.ok ? result : { ok: false, errors: result.errors.map(issueLine) };
}

// Every number a scene file may hold, tried just inside and just outside its limits; the
// cross-field limit on primary rays per pixel (distribution-effects §1).

function errorsOf(fields: Record<string, unknown>): string[] {
  const result = parseScene({ version: 1, ...fields });
  if (result.ok) throw new Error('expected the scene to be rejected');
  return result.errors.map(issueLine);
}

/** A scene file with one value set at a dotted path such as `camera.pixels.0`. */
function withValueAt(path: string, value: unknown): Record<string, unknown> {
  const root: Record<string, unknown> = { version: 1 };
  const keys = path.split('.');
  let node: Record<string, unknown> = root;
  keys.slice(0, -1).forEach((key, index) => {
    const nextIsIndex = /^\d+$/.test(keys[index + 1]!);
    node[key] ??= nextIsIndex ? defaultListAt(path, key) : {};
    node = node[key] as Record<string, unknown>;
  });
  node[keys.at(-1)!] = value;
  return root;
}

/** Lists the limit tests reach into: one valid light or object, or a valid pair/triple. */
function defaultListAt(path: string, key: string): unknown[] {
  if (key === 'lights') return [{ id: 'lamp', type: path.includes('samples') || path.includes('size') ? 'area' : 'spot' }];
  if (key === 'objects') return [{ id: 'thing' }];
  if (key === 'pixels' || key === 'imageSize' || key === 'size') return [1, 1];
  return [1, 1, 1];
}

describe('primary rays per pixel (distribution-effects §1)', () => {
  it('takes s²·n²·k = 1024 and refuses one more step, on the factor that broke it', () => {
    expect(parseScene({ version: 1, camera: { lensSamples: 4 }, settings: { supersampling: 2, timeSamples: 16 } }).ok).toBe(true);
    expect(errorsOf({ camera: { lensSamples: 8 }, settings: { supersampling: 8 } })).toEqual([
      'camera.lensSamples: makes supersampling² · lensSamples² · timeSamples = 8² · 8² · 1 = 4096 primary rays per pixel, more than 1024',
    ]);
    expect(errorsOf({ camera: { lensSamples: 4 }, settings: { supersampling: 3, timeSamples: 16 } })).toEqual([
      'settings.timeSamples: makes supersampling² · lensSamples² · timeSamples = 3² · 4² · 16 = 2304 primary rays per pixel, more than 1024',
    ]);
  });

  it('is checked alongside the other problems of the file', () => {
    const errors = errorsOf({ camera: { lensSamples: 8, aperture: 2 }, settings: { supersampling: 8 } });
    expect(errors).toHaveLength(2);
    expect(errors).toContain('camera.aperture: must be between 0 and 0.5, got 2');
  });
});

describe('limits at both ends', () => {
  // [path, lowest, highest, whole numbers only]
  it.each<[string, number, number, boolean]>([
    ['camera.fov', 1, 179, false],
    ['camera.pixels.0', 1, 64, true],
    ['camera.pixels.1', 1, 64, true],
    ['camera.screenDistance', 0.01, 100, false],
    ['camera.position.2', -10000, 10000, false],
    ['settings.maxDepth', 0, 10, true],
    ['settings.supersampling', 1, 8, true],
    ['settings.imageSize.0', 1, 4096, true],
    ['settings.background.0', 0, 1, false],
    ['objects.0.rotation.1', -10000, 10000, false],
    ['objects.0.scale.0', 0.001, 1000, false],
    ['objects.0.material.ambient', 0, 1, false],
    ['objects.0.material.diffuse', 0, 1, false],
    ['objects.0.material.specular', 0, 1, false],
    ['objects.0.material.shininess', 0, 10000, false],
    ['objects.0.material.refractiveIndex', 1, 4, false],
    ['lights.0.intensity', 0, 100, false],
    ['lights.0.ambient', 0, 1, false],
    ['lights.0.spotAngle', 1, 170, false],
    ['lights.0.angleAttenuation', 0, 64, false],
    ['lights.0.samples', 1, 10, true],
    ['lights.0.size.1', 0.01, 100, false],
    ['camera.aperture', 0, 0.5, false],
    ['camera.focusDistance', 0.05, 100, false],
    ['camera.lensSamples', 1, 8, true],
    ['settings.timeSamples', 1, 16, true],
    ['objects.0.material.roughness', 0, 1, false],
    ['objects.0.material.glossySamples', 1, 8, true],
    ['objects.0.velocity.0', -10, 10, false],
    ['objects.0.velocity.2', -10, 10, false],
  ])('%s: %d..%d', (path, lowest, highest, whole) => {
    const step = whole ? 1 : Math.max(Math.abs(highest - lowest) * 1e-3, 1e-6);
    const shownPath = path.replace(/\.(\d+)/g, '[$1]');
    for (const inside of [lowest, highest]) {
      const result = parseScene(withValueAt(path, inside));
      expect(result.ok ? [] : result.errors.map(issueLine)).toEqual([]);
    }
    for (const outside of [lowest - step, highest + step]) {
      expect(inLines(parseScene(withValueAt(path, outside)))).toEqual({
        ok: false,
        errors: [`${shownPath}: must be between ${lowest} and ${highest}, got ${outside}`],
      });
    }
  });

  it('takes up to 256 objects and 32 lights', () => {
    const objects = (count: number) => Array.from({ length: count }, (_, index) => ({ id: `o${index}` }));
    const lights = (count: number) => Array.from({ length: count }, (_, index) => ({ id: `l${index}` }));
    expect(parseScene({ version: 1, objects: objects(256), lights: lights(32) }).ok).toBe(true);
    expect(errorsOf({ objects: objects(257), lights: lights(33) })).toEqual([
      'objects: must have at most 256 items, got a list of 257 items',
      'lights: must have at most 32 items, got a list of 33 items',
    ]);
  });
});
