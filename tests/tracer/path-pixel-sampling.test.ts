import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { renderTile } from '../../src/tracer/render-tile.ts';
import { tracerSceneFrom } from '../support/test-scene.ts';

/**
 * `pixelSampling: "independent"` keeps path mode's pictures from before stratified pixel points
 * were its default (level 22 teaches the 1/√N of independent paths with them). The golden file
 * holds a small room, with a lens, a moving ball and glass, rendered by the tracer of commit
 * 1a21d63 (independent points only), as the bits of its Float32 colours.
 */
interface Golden {
  scene: { settings: Record<string, unknown> } & Record<string, unknown>;
  seed: number;
  rgbFloat32Base64: string;
}

const golden = JSON.parse(readFileSync('tests/golden/path-independent-points.json', 'utf8')) as Golden;

function render(pixelSampling: string): Float32Array {
  const scene = tracerSceneFrom({ ...golden.scene, settings: { ...golden.scene.settings, pixelSampling } });
  const [width, height] = scene.settings.imageSize;
  return renderTile(scene, { x: 0, y: 0, width, height }, { imageWidth: width, imageHeight: height, seed: golden.seed });
}

const bits = (rgb: Float32Array): Buffer => Buffer.from(rgb.buffer, rgb.byteOffset, rgb.byteLength);

describe('path mode pixel sampling', () => {
  it('independent points render the earlier pictures to the bit', () => {
    const expected = Buffer.from(golden.rgbFloat32Base64, 'base64');
    expect(bits(render('independent')).equals(expected)).toBe(true);
  });

  it('stratified points, the default, place the paths elsewhere', () => {
    const stratified = render('stratified');
    expect(bits(stratified).equals(Buffer.from(golden.rgbFloat32Base64, 'base64'))).toBe(false);
    const byDefault = tracerSceneFrom(golden.scene);
    expect(byDefault.settings.pixelSampling).toBe('stratified');
  });
});
