import { describe, expect, it } from 'vitest';
import { parseScene, parseSceneJson, type SceneParseResult } from '../../src/scene/scene-schema.ts';
import { issueLine } from '../../src/util/issue.ts';

/** A result with its problems as the English lines `rt validate` prints. */
function inLines(result: SceneParseResult) {
  return result.ok ? result : { ok: false, errors: result.errors.map(issueLine) };
}

/** The example scene of spec §1, word for word. */
const SPEC_EXAMPLE = {
  version: 1,
  camera: { position: [0, 1, 5], target: [0, 0.5, 0], fov: 45, pixels: [8, 6], screenDistance: 1 },
  settings: { shadows: true, maxDepth: 3, background: [0.7, 0.7, 0.7], supersampling: 1, imageSize: [512, 384] },
  objects: [
    {
      id: 'ball',
      shape: 'sphere',
      position: [0, 0.5, 0],
      rotation: [0, 0, 0],
      scale: [1, 1, 1],
      material: { color: [1, 0, 0], ambient: 0.2, diffuse: 1, specular: 0, shininess: 32, transparent: false, refractiveIndex: 1.5 },
    },
  ],
  lights: [
    {
      id: 'sun',
      type: 'point',
      position: [2, 4, 3],
      color: [1, 1, 1],
      intensity: 1,
      ambient: 0.1,
      diffuse: 1,
      specular: 1,
      distanceAttenuation: false,
    },
  ],
};

/** The errors for a scene file made of `version: 1` and `fields`; fails if it is valid. */
function errorsOf(fields: Record<string, unknown>): string[] {
  const result = parseScene({ version: 1, ...fields });
  if (result.ok) throw new Error('expected the scene to be rejected');
  return result.errors.map(issueLine);
}

/** A scene file with one object whose fields are `object` (plus an id). */
const withObject = (object: Record<string, unknown>) => ({ objects: [{ id: 'thing', ...object }] });
const withLight = (light: Record<string, unknown>) => ({ lights: [{ id: 'lamp', ...light }] });

describe('defaults', () => {
  it('fills every field of a file that has only a version', () => {
    expect(parseScene({ version: 1 })).toEqual({
      ok: true,
      scene: {
        version: 1,
        // No focusDistance: left out, the target is in focus.
        camera: { position: [0, 1, 5], target: [0, 0.5, 0], fov: 45, pixels: [8, 6], screenDistance: 1, aperture: 0, lensSamples: 1 },
        settings: {
          shadows: true,
          maxDepth: 3,
          background: [0.7, 0.7, 0.7],
          supersampling: 1,
          samplePattern: 'grid',
          imageSize: [512, 384],
          dithering: false,
          encoding: 'none',
          lightTypes: { point: true, spot: true, area: true },
          timeSamples: 1,
          timePattern: 'jittered',
          integrator: 'whitted',
          pathSamples: 16,
          pixelSampling: 'stratified',
          bounceSampling: 'cosine',
          lightSampling: true,
          russianRoulette: false,
          exposure: 0,
        },
        objects: [],
        lights: [],
      },
    });
  });

  it('fills an object and each light type from its id alone', () => {
    const result = parseScene({
      version: 1,
      objects: [{ id: 'ball' }],
      lights: [{ id: 'bulb' }, { id: 'spot', type: 'spot' }, { id: 'panel', type: 'area' }],
    });
    if (!result.ok) throw new Error(result.errors.map(issueLine).join('\n'));
    const common = {
      position: [0, 3, 0],
      color: [1, 1, 1],
      intensity: 1,
      ambient: 0.1,
      diffuse: 1,
      specular: 1,
      distanceAttenuation: false,
    };
    expect(result.scene.objects).toEqual([
      {
        id: 'ball',
        shape: 'sphere',
        position: [0, 0, 0],
        rotation: [0, 0, 0],
        scale: [1, 1, 1],
        velocity: [0, 0, 0],
        material: {
          color: [1, 1, 1],
          ambient: 0.2,
          diffuse: 1,
          specular: 0,
          shininess: 32,
          transparent: false,
          refractiveIndex: 1.5,
          roughness: 0,
          glossySamples: 3,
        },
      },
    ]);
    expect(result.scene.lights).toEqual([
      { id: 'bulb', type: 'point', ...common },
      { id: 'spot', type: 'spot', ...common, rotation: [0, 0, 0], spotAngle: 45, angleAttenuation: 1 },
      { id: 'panel', type: 'area', ...common, rotation: [0, 0, 0], angleAttenuation: 1, size: [1, 1], samples: 3, shape: 'rectangle' },
    ]);
  });

  it('gives every parsed scene its own default lists', () => {
    const first = parseScene({ version: 1, objects: [{ id: 'a' }] });
    const second = parseScene({ version: 1, objects: [{ id: 'b' }] });
    if (!first.ok || !second.ok) throw new Error('expected both scenes to be valid');
    first.scene.objects[0]!.position[0] = 7;
    first.scene.camera.position[0] = 7;
    expect(second.scene.objects[0]!.position).toEqual([0, 0, 0]);
    expect(second.scene.camera.position).toEqual([0, 1, 5]);
  });
});

describe('valid scenes', () => {
  it('accepts the example of spec §1 and keeps its values', () => {
    const result = parseScene(SPEC_EXAMPLE);
    if (!result.ok) throw new Error(result.errors.map(issueLine).join('\n'));
    expect(result.scene).toMatchObject(SPEC_EXAMPLE);
  });

  it('accepts every mesh asset name on a mesh object', () => {
    for (const mesh of ['prism', 'capsule', 'wine-glass', 'character']) {
      expect(parseScene({ version: 1, ...withObject({ shape: 'mesh', mesh }) }).ok).toBe(true);
    }
  });

  it('accepts a name on the scene, an object and a light', () => {
    const result = parseScene({ version: 1, name: 'Lesson 1', ...withObject({ name: 'Ball' }), ...withLight({ name: 'Sun' }) });
    expect(result.ok).toBe(true);
  });

  it('accepts a name per language, as level texts have them, and keeps it as written', () => {
    const name = { en: 'Red ball', nl: 'Rode bal' };
    const result = parseScene({
      version: 1,
      name: { en: 'Two mirrors' },
      ...withObject({ name }),
      ...withLight({ name: { en: 'Key light', nl: 'Hoofdlamp' } }),
    });
    if (!result.ok) throw new Error(result.errors.map(issueLine).join('\n'));
    expect([result.scene.name, result.scene.objects[0].name, result.scene.lights[0].name]).toEqual([
      { en: 'Two mirrors' },
      name,
      { en: 'Key light', nl: 'Hoofdlamp' },
    ]);
  });
});

describe('each kind of problem reads as "path: reason"', () => {
  it.each<[string, unknown, string]>([
    ['a number', 5, '(root): must be an object, got 5'],
    ['null', null, '(root): must be an object, got null'],
    ['a list', [], '(root): must be an object, got a list of 0 items'],
    ['no version', {}, 'version: is required'],
    ['another version', { version: 2 }, 'version: must be 1, got 2'],
  ])('the whole file is %s', (_what, input, message) => {
    expect(inLines(parseScene(input))).toEqual({ ok: false, errors: [message] });
  });

  it.each<[Record<string, unknown>, string]>([
    [{ camera: { zoom: 2 } }, 'camera: unknown field "zoom"'],
    [{ camera: { zoom: 2, tilt: 1 } }, 'camera: unknown fields "zoom", "tilt"'],
    [{ colour: [1, 1, 1] }, '(root): unknown field "colour"'],
    [{ camera: { fov: 'wide' } }, 'camera.fov: must be a number, got "wide"'],
    [{ camera: { fov: Number.POSITIVE_INFINITY } }, 'camera.fov: must be a number, got Infinity'],
    [{ camera: { fov: Number.NaN } }, 'camera.fov: must be a number, got NaN'],
    [{ camera: { position: [0, 1] } }, 'camera.position: must be a list of 3 numbers, got a list of 2 items'],
    [{ camera: { position: '0 1 5' } }, 'camera.position: must be a list of 3 numbers, got "0 1 5"'],
    [{ camera: { position: [0, 0.5, 0] } }, 'camera.target: must differ from camera.position'],
    [{ camera: { pixels: [8, 6.5] } }, 'camera.pixels[1]: must be a whole number, got 6.5'],
    [{ settings: { imageSize: [2.5, 384] } }, 'settings.imageSize[0]: must be a whole number, got 2.5'],
    [{ settings: { shadows: 'yes' } }, 'settings.shadows: must be true or false, got "yes"'],
    [{ settings: { samplePattern: 'poisson' } }, 'settings.samplePattern: must be one of grid, jittered, random, got "poisson"'],
    [{ settings: { timePattern: 'stratified' } }, 'settings.timePattern: must be one of grid, jittered, random, got "stratified"'],
    [{ settings: { encoding: 'gamma' } }, 'settings.encoding: must be one of none, linear, srgb, got "gamma"'],
    [{ settings: { background: [0.5, 2, 0] } }, 'settings.background[1]: must be between 0 and 1, got 2'],
    [{ settings: { lightTypes: { laser: true } } }, 'settings.lightTypes: unknown field "laser"'],
    [{ objects: {} }, 'objects: must be a list, got an object'],
    [{ objects: [7] }, 'objects[0]: must be an object, got 7'],
    [{ objects: [{}] }, 'objects[0].id: is required'],
    [{ objects: [{ id: '' }] }, 'objects[0].id: must not be empty'],
    [{ objects: [{ id: 12 }] }, 'objects[0].id: must be a string, got 12'],
    [{ objects: [{ id: [] }] }, 'objects[0].id: must be a string, got a list of 0 items'],
    [{ objects: [{ id: 'x'.repeat(65) }] }, 'objects[0].id: must be at most 64 characters long'],
    [withObject({ name: 'x'.repeat(101) }), 'objects[0].name: must be at most 100 characters long'],
    [withObject({ name: { en: 'Ball', nl: 'x'.repeat(101) } }), 'objects[0].name.nl: must be at most 100 characters long'],
    [
      withObject({ name: { nl: 'Bal' } }),
      'objects[0].name: must be a text, or { "en": …, "nl": … } with a text per language (en is required; each at most 100 characters)',
    ],
    [withObject({ name: { en: 'Ball', de: 'Kugel' } }), 'objects[0].name: unknown field "de"'],
    [
      withObject({ name: 7 }),
      'objects[0].name: must be a text, or { "en": …, "nl": … } with a text per language (en is required; each at most 100 characters)',
    ],
    [withObject({ shape: 'cone' }), 'objects[0].shape: must be one of sphere, box, cylinder, plane, mesh, got "cone"'],
    [withObject({ shape: 'mesh' }), 'objects[0].mesh: is required when shape is "mesh" (one of prism, capsule, wine-glass, character)'],
    [withObject({ shape: 'mesh', mesh: 'teapot' }), 'objects[0].mesh: must be one of prism, capsule, wine-glass, character, got "teapot"'],
    [withObject({ mesh: 'prism' }), 'objects[0].mesh: is only allowed when shape is "mesh"'],
    [withObject({ shape: 'box', mesh: 'prism' }), 'objects[0].mesh: is only allowed when shape is "mesh"'],
    [withObject({ scale: [1, 0, 1] }), 'objects[0].scale[1]: must be between 0.001 and 1000, got 0'],
    [withObject({ material: { color: [1, 0, 0], shine: 3 } }), 'objects[0].material: unknown field "shine"'],
    [withObject({ material: { transparent: 1 } }), 'objects[0].material.transparent: must be true or false, got 1'],
    [withLight({ type: 'laser' }), 'lights[0].type: must be one of point, spot, area, got "laser"'],
    [withLight({ type: 7 }), 'lights[0].type: must be one of point, spot, area, got 7'],
    [withLight({ type: 'spot', spotAngle: 400 }), 'lights[0].spotAngle: must be between 1 and 170, got 400'],
    [withLight({ spotAngle: 30 }), 'lights[0]: unknown field "spotAngle"'],
    [withLight({ type: 'spot', size: [1, 1] }), 'lights[0]: unknown field "size"'],
    [withLight({ type: 'area', shape: 'hexagon' }), 'lights[0].shape: must be one of rectangle, disc, got "hexagon"'],
    [withLight({ type: 'area', samples: 2.5 }), 'lights[0].samples: must be a whole number, got 2.5'],
  ])('%j', (fields, message) => {
    expect(errorsOf(fields)).toEqual([message]);
  });
});

describe('ids', () => {
  it('reports an object id used twice at its second use', () => {
    expect(errorsOf({ objects: [{ id: 'ball' }, { id: 'cube' }, { id: 'ball' }] })).toEqual(['objects[2].id: "ball" is used twice']);
  });

  it('reports a light id used twice', () => {
    expect(errorsOf({ lights: [{ id: 'sun' }, { id: 'sun' }] })).toEqual(['lights[1].id: "sun" is used twice']);
  });

  it('does not let a light take an object id', () => {
    expect(errorsOf({ objects: [{ id: 'ball' }], lights: [{ id: 'ball' }] })).toEqual(['lights[0].id: "ball" is used twice']);
  });

  it('reports every repeat of an id used three times', () => {
    expect(errorsOf({ objects: [{ id: 'a' }, { id: 'a' }], lights: [{ id: 'a' }] })).toEqual([
      'objects[1].id: "a" is used 3 times',
      'lights[0].id: "a" is used 3 times',
    ]);
  });

  it('treats ids as case-sensitive', () => {
    expect(parseScene({ version: 1, objects: [{ id: 'Ball' }, { id: 'ball' }] }).ok).toBe(true);
  });
});

describe('every problem is listed, not just the first', () => {
  it('lists type errors, range errors, unknown fields, duplicate ids and mesh rules together', () => {
    const errors = errorsOf({
      camera: { fov: 'wide', zoom: 2 },
      settings: { imageSize: [2.5, 5000] },
      objects: [{ id: 'ball' }, { id: 'ball', shape: 'cone' }, { id: 'm', shape: 'mesh', position: 'here' }],
      lights: [{ id: 'sun', type: 'spot', spotAngle: 400 }, 7],
    });
    expect(errors.sort()).toEqual(
      [
        'camera.fov: must be a number, got "wide"',
        'camera: unknown field "zoom"',
        'settings.imageSize[0]: must be a whole number, got 2.5',
        'settings.imageSize[1]: must be between 1 and 4096, got 5000',
        'objects[1].shape: must be one of sphere, box, cylinder, plane, mesh, got "cone"',
        'objects[1].id: "ball" is used twice',
        'objects[2].position: must be a list of 3 numbers, got "here"',
        'objects[2].mesh: is required when shape is "mesh" (one of prism, capsule, wine-glass, character)',
        'lights[0].spotAngle: must be between 1 and 170, got 400',
        'lights[1]: must be an object, got 7',
      ].sort(),
    );
  });
});

describe('scene file text', () => {
  it('parses the spec example from its JSON text', () => {
    expect(parseSceneJson(JSON.stringify(SPEC_EXAMPLE, null, 2)).ok).toBe(true);
  });

  it('accepts a file that starts with a byte-order mark', () => {
    expect(parseSceneJson('\uFEFF{ "version": 1 }').ok).toBe(true);
  });

  it.each<[string, string]>([
    ['', 'at line 1, column 1: expected a value, found the end of the text'],
    ['{ "version": 1,\n  "camera": }', 'at line 2, column 13: expected a value, found "}"'],
    ['{ "version": 1,\n}', 'at line 2, column 1: expected a field name in double quotes, found "}"'],
    ["{ 'version': 1 }", 'at line 1, column 3: expected a field name in double quotes, found "\'"'],
    ['{ "version" 1 }', 'at line 1, column 13: expected ":", found "1"'],
    ['{ "version": 1 "name": "x" }', 'at line 1, column 16: expected "," or "}", found "\\""'],
    ['{ "objects": [1 2] }', 'at line 1, column 17: expected "," or "]", found "2"'],
    ['{ "version": 1', 'at line 1, column 15: expected "," or "}", found the end of the text'],
    ['{ "name": "two\nlines" }', 'at line 1, column 15: expected a closing \'"\' (write a line break inside a string as \\n), found "\\n"'],
    ['{ "name": "\\q" }', 'at line 1, column 12: expected an escape such as \\n, \\" or \\u00e9, found "\\\\"'],
    ['{ "version": 01 }', 'at line 1, column 15: expected "," or "}", found "1"'],
    ['{ "version": 1 } extra', 'at line 1, column 18: expected the end of the text, found "e"'],
  ])('%j is not JSON', (text, where) => {
    expect(inLines(parseSceneJson(text))).toEqual({ ok: false, errors: [`(root): not valid JSON ${where}`] });
  });

  it('checks the scene once the JSON is fine', () => {
    expect(inLines(parseSceneJson('{ "version": 1, "camera": { "fov": 400 } }'))).toEqual({
      ok: false,
      errors: ['camera.fov: must be between 1 and 179, got 400'],
    });
  });
});

describe('random input', () => {
  /** mulberry32: a tiny seeded generator, so a failure can be replayed. */
  function randomSource(seed: number) {
    let state = seed;
    return () => {
      state = (state + 0x6d2b79f5) | 0;
      let t = Math.imul(state ^ (state >>> 15), 1 | state);
      t = (t + Math.imul(t ^ (t >>> 7), 61 | t)) ^ t;
      return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
    };
  }

  const FIELD_NAMES = [
    'version',
    'camera',
    'settings',
    'objects',
    'lights',
    'id',
    'type',
    'shape',
    'mesh',
    'position',
    'rotation',
    'scale',
    'material',
    'color',
    'fov',
    'pixels',
    'samples',
    'size',
    'spotAngle',
    'imageSize',
    'lightTypes',
    'x',
  ];
  const ODD_NUMBERS = [0, -0, 1, -1, 0.5, 1e308, -1e308, Number.NaN, Number.POSITIVE_INFINITY, 2 ** 53, 170, 4096];
  const ODD_STRINGS = ['', 'sphere', 'mesh', 'prism', 'spot', 'area', 'ball', '__proto__', 'constructor', '\u0000', '😀'];

  function randomValue(random: () => number, depth: number): unknown {
    const pick = <T>(items: readonly T[]): T => items[Math.floor(random() * items.length)]!;
    switch (Math.floor(random() * (depth > 3 ? 5 : 7))) {
      case 0:
        return pick(ODD_NUMBERS);
      case 1:
        return random() * 20 - 10;
      case 2:
        return pick(ODD_STRINGS);
      case 3:
        return pick([true, false, null, undefined]);
      case 4:
        return pick([[], {}, [0, 0, 0], [1, 1]]);
      case 5:
        return Array.from({ length: Math.floor(random() * 4) }, () => randomValue(random, depth + 1));
      default:
        return Object.fromEntries(Array.from({ length: Math.floor(random() * 5) }, () => [pick(FIELD_NAMES), randomValue(random, depth + 1)]));
    }
  }

  /** The spec example with one value somewhere inside replaced by a random one. */
  function mutatedExample(random: () => number): unknown {
    const scene = structuredClone(SPEC_EXAMPLE) as Record<string, unknown>;
    let node: Record<string, unknown> = scene;
    for (;;) {
      const keys = Object.keys(node);
      const key = keys[Math.floor(random() * keys.length)]!;
      const child = node[key];
      if (typeof child === 'object' && child !== null && random() < 0.7) node = child as Record<string, unknown>;
      else {
        node[key] = randomValue(random, 2);
        return scene;
      }
    }
  }

  function expectWellFormed(result: ReturnType<typeof parseScene>): void {
    if (result.ok) {
      // A parsed scene is a valid scene file in its own right, and parses to itself.
      expect(parseScene(result.scene)).toEqual(result);
    } else {
      expect(result.errors.length).toBeGreaterThan(0);
      for (const error of result.errors) expect(issueLine(error)).toMatch(/^\S+: \S/);
    }
  }

  it('never throws on random values and always answers ok or with problems', () => {
    const random = randomSource(20240601);
    for (let round = 0; round < 400; round++) {
      expectWellFormed(parseScene(round % 2 === 0 ? randomValue(random, 0) : mutatedExample(random)));
    }
  });

  it('never throws on random cuts and edits of scene text', () => {
    const random = randomSource(7);
    const text = JSON.stringify(SPEC_EXAMPLE);
    for (let round = 0; round < 300; round++) {
      const start = Math.floor(random() * text.length);
      const end = start + Math.floor(random() * 10);
      const edited = text.slice(0, start) + String.fromCharCode(32 + Math.floor(random() * 95)) + text.slice(end);
      expectWellFormed(parseSceneJson(random() < 0.2 ? text.slice(0, start) : edited));
    }
  });
});
