// The hint under Lens samples (n) says what the tracer sends per pixel sample
// (src/tracer/render-pixel.ts): issue 37 found "1 × 1 = 1 lens rays".
import { expect, test } from 'vitest';
import { lensSamplesHint } from '../../../../src/ui/lab/panels/distribution-specs.ts';

test('one lens sample is said plainly, as one ray from a random point of the lens', () => {
  expect(lensSamplesHint(1, 0.165)).toBe('One lens ray per sample, from a random point of the lens');
});

test('more lens samples give n × n rays', () => {
  expect(lensSamplesHint(2, 0.165)).toBe('2 × 2 = 4 lens rays per sample');
  expect(lensSamplesHint(5, 0.3)).toBe('5 × 5 = 25 lens rays per sample');
});

test('a pinhole sends one ray whatever n is', () => {
  expect(lensSamplesHint(4, 0)).toBe('A pinhole: one ray per sample');
  expect(lensSamplesHint(1, 0)).toBe('A pinhole: one ray per sample');
});
