import { describe, expect, it } from 'vitest';
import { judge, type LabAnswer, type Tolerance } from '../../src/quest/code-labs/code-lab-grading.ts';

/** Judges one answer against the tracer's `expected`. */
const check = (tolerance: Tolerance, expected: LabAnswer, returned: unknown) => judge({ kind: 'edge', args: [], expected }, { returned }, tolerance, 0);

const vector: Tolerance = { answer: 'vector', relative: 1e-9 };
const direction: Tolerance = { answer: 'direction', radians: 1e-6, length: 1e-9 };
const colour: Tolerance = { answer: 'colour', relative: 1e-9 };
const boolean: Tolerance = { answer: 'boolean' };
const v = (x: number, y: number, z: number) => ({ x, y, z });

describe('a code lab’s kinds of answer', () => {
  it('compares a vector component by component, within its tolerance of the vector’s length', () => {
    expect(check(vector, v(1, 2, 3), v(1, 2, 3 + 1e-9))).toBeNull();
    expect(check(vector, v(1, 2, 3), v(1, 2, 3.001))).toMatchObject({ reason: 'wrong-value', got: v(1, 2, 3.001), gotValue: v(1, 2, 3.001) });
    expect(check(vector, v(1, 2, 3), v(1, 2, NaN))).toMatchObject({ reason: 'not-a-number', got: v(1, 2, NaN) });
    expect(check(vector, v(1, 2, 3), { r: 1, g: 2, b: 3 })).toMatchObject({ reason: 'wrong-type' });
    expect(check(vector, v(1, 2, 3), 3)).toMatchObject({ reason: 'wrong-type', got: 3 });
  });

  it('compares a direction by its angle, and asks for length 1', () => {
    const slanted = v(0.6, 0.8, 0);
    expect(check(direction, slanted, v(0.6, 0.8, 1e-8))).toBeNull();
    expect(check(direction, slanted, v(0.8, 0.6, 0))).toMatchObject({ reason: 'wrong-value' });
    expect(check(direction, slanted, v(1.2, 1.6, 0))).toMatchObject({ reason: 'not-unit', gotValue: v(1.2, 1.6, 0) });
    expect(check(direction, slanted, v(-0.6, -0.8, 0))).toMatchObject({ reason: 'wrong-value' });
  });

  it('takes null where the tracer’s answer is null, and only there', () => {
    expect(check(direction, null, null)).toBeNull();
    expect(check(direction, null, v(0, 1, 0))).toMatchObject({ reason: 'expected-miss', got: v(0, 1, 0) });
    expect(check(direction, v(0, 1, 0), null)).toMatchObject({ reason: 'expected-hit', got: null });
  });

  it('compares a colour channel by channel, within its tolerance of the brightest', () => {
    expect(check(colour, { r: 0.5, g: 0.25, b: 2 }, { r: 0.5, g: 0.25, b: 2 + 1e-9 })).toBeNull();
    expect(check(colour, { r: 0.5, g: 0.25, b: 2 }, { r: 0.5, g: 0.26, b: 2 })).toMatchObject({ reason: 'wrong-value', got: { r: 0.5, g: 0.26, b: 2 } });
    expect(check(colour, { r: 0.5, g: 0.25, b: 2 }, v(0.5, 0.25, 2))).toMatchObject({ reason: 'wrong-type' });
  });

  it('asks for exactly true or false', () => {
    expect(check(boolean, true, true)).toBeNull();
    expect(check(boolean, true, false)).toMatchObject({ reason: 'wrong-value', got: false, gotValue: false });
    expect(check(boolean, false, 0)).toMatchObject({ reason: 'wrong-type', got: 0 });
    expect(check(boolean, false, null)).toMatchObject({ reason: 'wrong-type', got: null });
  });
});
