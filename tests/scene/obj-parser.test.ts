import { describe, expect, it } from 'vitest';
import { ObjLineReader } from '../../src/scene/obj-line-reader.ts';
import { parseObj } from '../../src/scene/obj-parser.ts';

/** A unit square in the XY plane, facing +Z. */
const SQUARE_CORNERS = 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n';

describe('parseObj: what it reads', () => {
  it('reads a triangle with v//vn corners', () => {
    const mesh = parseObj('v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\n');
    expect([...mesh.positions]).toEqual([0, 0, 0, 1, 0, 0, 0, 1, 0]);
    expect([...(mesh.normals ?? [])]).toEqual([0, 0, 1, 0, 0, 1, 0, 0, 1]);
    expect([...mesh.indices]).toEqual([0, 1, 2]);
  });

  it('fan-triangulates quads and larger polygons from their first corner', () => {
    expect([...parseObj(`${SQUARE_CORNERS}f 1 2 3 4`).indices]).toEqual([0, 1, 2, 0, 2, 3]);
    const pentagon = parseObj(`${SQUARE_CORNERS}v 0.5 1.5 0\nf 1 2 3 5 4`);
    expect([...pentagon.indices]).toEqual([0, 1, 2, 0, 2, 3, 0, 3, 4]);
  });

  it('counts negative indices back from the last vertex and normal defined so far', () => {
    const relative = parseObj(`${SQUARE_CORNERS}vn 0 0 1\nf -4//-1 -3//-1 -2//-1 -1//-1`);
    const absolute = parseObj(`${SQUARE_CORNERS}vn 0 0 1\nf 1//1 2//1 3//1 4//1`);
    expect(relative).toEqual(absolute);
  });

  it('shares a vertex between faces only when both its position and its normal match', () => {
    const shared = parseObj(`${SQUARE_CORNERS}vn 0 0 1\nf 1//1 2//1 3//1\nf 1//1 3//1 4//1`);
    expect(shared.positions.length / 3).toBe(4);
    expect([...shared.indices]).toEqual([0, 1, 2, 0, 2, 3]);

    const creased = parseObj(`${SQUARE_CORNERS}vn 0 0 1\nvn 0 1 0\nf 1//1 2//1 3//1\nf 1//2 3//2 4//2`);
    expect(creased.positions.length / 3).toBe(6);
    expect([...creased.indices]).toEqual([0, 1, 2, 3, 4, 5]);
  });

  it('reads v/vt and v/vt/vn corners, ignoring the texture coordinates', () => {
    const withNormals = parseObj(`${SQUARE_CORNERS}vt 0 0\nvn 0 0 1\nf 1/1/1 2/1/1 3/1/1`);
    expect(withNormals.normals).not.toBeNull();
    expect([...withNormals.indices]).toEqual([0, 1, 2]);
    expect(parseObj(`${SQUARE_CORNERS}vt 0 0\nf 1/1 2/1 3/1`).normals).toBeNull();
  });

  it('has no normals when any face corner lacks one, sharing vertices by position alone', () => {
    const mixed = parseObj(`${SQUARE_CORNERS}vn 0 0 1\nf 1//1 2//1 3//1\nf 1 3 4`);
    expect(mixed.normals).toBeNull();
    expect(mixed.positions.length / 3).toBe(4);
  });

  it('normalizes normals', () => {
    const mesh = parseObj('v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 2\nf 1//1 2//1 3//1');
    expect(mesh.normals?.[2]).toBe(1);
  });

  it('skips comments, blank lines, CRLF line ends, tabs and statements it has no use for', () => {
    const text = [
      '# a comment',
      'mtllib scene.mtl',
      'o thing',
      'g part',
      '',
      'v 0 0 0 1   # a w coordinate and a trailing comment',
      'v\t1 0 0\r',
      'v 0 1 0 0.5 0.5 0.5',
      'vt 0 0',
      'usemtl glass',
      's off',
      'l 1 2',
      '   f 1 2 3   ',
    ].join('\n');
    const mesh = parseObj(text);
    expect([...mesh.positions]).toEqual([0, 0, 0, 1, 0, 0, 0, 1, 0]);
    expect([...mesh.indices]).toEqual([0, 1, 2]);
  });
});

describe('ObjLineReader.number', () => {
  it('reads every number exactly as Number() does, through its fast path or not', () => {
    const words = ['0', '-0', '1', '+1.5', '.5', '1.', '-0.57735', '123.45678', '0.1', '0.30000000000000004', '1e-7', '-2.5E3', '123456789012345678'];
    // Pseudo-random decimals like those the generator writes, and the awkward 15-16 digit edge.
    for (let i = 1; i <= 2000; i++) words.push((Math.sin(i) * 10 ** (i % 4)).toFixed(i % 7), (Math.cos(i) / 3).toPrecision(15 + (i % 3)));
    const reader = new ObjLineReader(words.join(' '));
    reader.nextLine();
    const read = words.map(() => reader.number());
    expect(read).toEqual(words.map(Number));
    expect(reader.hasWord()).toBe(false);
  });
});

describe('parseObj: bad input names the file and line', () => {
  const cases: [what: string, text: string, message: string][] = [
    ['no faces', 'v 0 0 0\n', 'prism.obj: no faces (f lines) found'],
    ['a vertex index past the end', `${SQUARE_CORNERS}\nf 1 2 40`, 'prism.obj line 6: vertex index 40 out of range (file has 4 vertices before this line)'],
    ['a negative index past the start', `${SQUARE_CORNERS}f 1 2 -5`, 'prism.obj line 5: vertex index -5 out of range (file has 4 vertices before this line)'],
    [
      'a normal index past the end',
      `${SQUARE_CORNERS}vn 0 0 1\nf 1//1 2//1 3//2`,
      'prism.obj line 6: normal index 2 out of range (file has 1 normal before this line)',
    ],
    ['index 0', `${SQUARE_CORNERS}f 0 1 2`, 'prism.obj line 5: vertex index 0 is not valid (OBJ indices start at 1)'],
    ['a fractional index', `${SQUARE_CORNERS}f 1 2 2.5`, 'prism.obj line 5: face corner "2.5" is not v, v/vt, v//vn or v/vt/vn with whole-number indices'],
    ['a corner without a vertex index', `${SQUARE_CORNERS}f /1 2 3`, 'prism.obj line 5: face corner "/1" is not'],
    ['a non-numeric normal index', `${SQUARE_CORNERS}vn 0 0 1\nf 1//1 2//1 3//x`, 'prism.obj line 6: face corner "3//x" is not'],
    ['a face with two corners', `${SQUARE_CORNERS}f 1 2`, 'prism.obj line 5: face needs at least 3 vertices, got 2'],
    ['a non-numeric coordinate', 'v 0 zero 0\nf 1 1 1', 'prism.obj line 1: vertex coordinate "zero" is not a number'],
    ['a missing coordinate', 'v 0 0\nf 1 1 1', 'prism.obj line 1: vertex needs 3 coordinates (x y z), got 2'],
    ['a non-numeric normal', 'vn 0 0 one', 'prism.obj line 1: normal coordinate "one" is not a number'],
    ['a zero normal', 'vn 0 0 0', 'prism.obj line 1: normal has zero length'],
  ];
  for (const [what, text, message] of cases) {
    it(`rejects ${what}`, () => {
      expect(() => parseObj(text, 'prism.obj')).toThrow(message);
    });
  }

  it('calls the file "OBJ" when it has no name', () => {
    expect(() => parseObj('')).toThrow('OBJ: no faces (f lines) found');
  });
});
