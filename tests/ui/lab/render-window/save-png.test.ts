import { describe, expect, it } from 'vitest';
import { pngFileName } from '../../../../src/ui/lab/render-window/save-png.ts';

describe('pngFileName', () => {
  it('names the scene and the size', () => {
    expect(pngFileName('Three spheres and a box', 512, 384)).toBe('ray-tracer-quest-three-spheres-and-a-box-512x384.png');
  });

  it("marks a cancelled render's picture as partial", () => {
    expect(pngFileName('Three spheres and a box', 512, 384, true)).toBe('ray-tracer-quest-three-spheres-and-a-box-512x384-partial.png');
    expect(pngFileName(undefined, 64, 48, true)).toBe('ray-tracer-quest-64x48-partial.png');
  });

  it('leaves the scene out when it has no name, or no letters a file name can keep', () => {
    expect(pngFileName(undefined, 512, 384)).toBe('ray-tracer-quest-512x384.png');
    expect(pngFileName('  ***  ', 64, 48)).toBe('ray-tracer-quest-64x48.png');
  });

  it('keeps letters without their accents and drops punctuation, slashes and dots', () => {
    expect(pngFileName('Één prisma / ../glass: "test"', 100, 75)).toBe('ray-tracer-quest-een-prisma-glass-test-100x75.png');
  });

  it('shortens a long name', () => {
    const name = pngFileName('a'.repeat(200), 1, 1);
    expect(name).toBe(`ray-tracer-quest-${'a'.repeat(40)}-1x1.png`);
  });
});
