// The scene schema's problems come as codes with values (src/util/issue.ts): zod keeps only
// a message per issue, so scene-issues.ts leaves each reason on the raw issue, relying on
// zod to copy the raw issue's own fields into its result. If zod stops doing that, the
// reasons fall back to English words and this test says so.
import { describe, expect, it } from 'vitest';
import { parseScene, parseSceneJson } from '../../src/scene/scene-schema.ts';

function reasonsOf(input: unknown) {
  const result = parseScene(input);
  if (result.ok) throw new Error('expected the scene to be rejected');
  return result.errors;
}

describe('scene problems as data', () => {
  it('carry a code and its values from the error map, the schema parts and the rules', () => {
    const errors = reasonsOf({
      version: 1,
      camera: { fov: 400, position: [0, 1, 5], target: [0, 1, 5], lensSamples: 8 },
      settings: { maxDepth: 'deep', supersampling: 8, samples: 4 },
      objects: [
        { id: 'ball', position: [0, 1] },
        { id: 'ball', shape: 'sphere', mesh: 'teapot' },
      ],
    });
    expect(errors).toEqual(
      expect.arrayContaining([
        { path: 'camera.fov', reason: { code: 'outOfRange', lowest: 1, highest: 179, got: { kind: 'literal', text: '400' } } },
        { path: 'camera.target', reason: { code: 'targetIsPosition' } },
        { path: 'settings.maxDepth', reason: { code: 'wrongType', expected: 'number', got: { kind: 'literal', text: '"deep"' } } },
        { path: 'settings', reason: { code: 'unknownFields', names: ['samples'] } },
        { path: 'objects[0].position', reason: { code: 'notListOf', length: 3, items: 'numbers', got: { kind: 'list', length: 2 } } },
        { path: 'objects[1].id', reason: { code: 'idReused', id: 'ball', uses: 2 } },
        { path: 'objects[1].mesh', reason: { code: 'meshNotAllowed' } },
        { path: 'camera.lensSamples', reason: { code: 'tooManyRays', supersampling: 8, lensSamples: 8, timeSamples: 1, rays: 4096, most: 1024 } },
      ]),
    );
    expect(errors.filter((error) => error.reason.code === 'worded')).toEqual([]);
  });

  it('say where a text stops being JSON', () => {
    expect(parseSceneJson('{ "version": 1')).toEqual({
      ok: false,
      errors: [{ path: '(root)', reason: { code: 'notJson', line: 1, column: 15, expected: { kind: 'comma or close', close: '}' }, found: null } }],
    });
  });
});
