import { describe, expect, it } from 'vitest';
import { pfmBytes } from '../../src/cli/pfm-file.ts';

describe('the PFM file of a linear picture', () => {
  it('has the colour header, the size, a little-endian scale, then the rows from the bottom up', () => {
    // Two rows of one pixel: the top one red 2.5 (over 1: nothing is clamped), the bottom one blue.
    const rgb = Float32Array.of(2.5, 0, 0, 0, 0, 0.25);
    const bytes = pfmBytes(rgb, 1, 2);
    const header = 'PF\n1 2\n-1.0\n';
    expect(new TextDecoder().decode(bytes.subarray(0, header.length))).toBe(header);
    const floats = new DataView(bytes.buffer, header.length);
    const read = Array.from({ length: 6 }, (_, i) => floats.getFloat32(i * 4, true));
    expect(read).toEqual([0, 0, 0.25, 2.5, 0, 0]);
  });
});
