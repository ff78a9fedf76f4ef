import { describe, expect, it } from 'vitest';
import { renderTile } from '../../src/tracer/render-tile.ts';
import { tracePixel } from '../../src/tracer/trace-pixel.ts';
import { matte, pointLight, tracerSceneFrom } from '../support/test-scene.ts';

/** Depth of field (distribution-effects §2): the thin lens, checked against its geometry. */

const SIZE = 120;
const FOV = 30;

function render(file: Record<string, unknown>, size = SIZE): Float32Array {
  const scene = tracerSceneFrom(file);
  return renderTile(scene, { x: 0, y: 0, width: size, height: size }, { imageWidth: size, imageHeight: size, seed: 2 });
}

/** A tiny self-lit ball (colour 1 where hit, black around it) on the axis at depth z. */
function pointScene(z: number, aperture: number, focusDistance: number, radius: number) {
  return {
    camera: { position: [0, 0, 0], target: [0, 0, -1], fov: FOV, aperture, focusDistance, lensSamples: 8 },
    settings: { background: [0, 0, 0] },
    objects: [
      { id: 'dot', shape: 'sphere', position: [0, 0, -z], scale: [2 * radius, 2 * radius, 2 * radius], material: matte([1, 1, 1], { ambient: 1, diffuse: 0 }) },
    ],
  };
}

/** The spread of the image's brightness along x: its standard deviation in pixels, and its farthest lit pixel from the centre. */
function spread(rgb: Float32Array, size: number): { sigma: number; reach: number } {
  let total = 0;
  let moment = 0;
  let reach = 0;
  const centre = size / 2;
  for (let y = 0; y < size; y++) {
    for (let x = 0; x < size; x++) {
      const value = rgb[(y * size + x) * 3];
      if (value <= 0) continue;
      const dx = x + 0.5 - centre;
      total += value;
      moment += value * dx * dx;
      reach = Math.max(reach, Math.hypot(dx, y + 0.5 - centre));
    }
  }
  return { sigma: Math.sqrt(moment / total), reach };
}

describe('depth of field', () => {
  it('a point on the plane in focus stays sharp whatever the aperture', () => {
    // A matte card standing exactly in the plane in focus, lit from the camera; a ball far behind it.
    const file = (aperture: number) => ({
      camera: { position: [0, 0, 0], target: [0, 0, -1], fov: FOV, aperture, focusDistance: 2, lensSamples: 4 },
      settings: { background: [0, 0, 0] },
      objects: [
        { id: 'card', shape: 'plane', position: [-0.15, 0, -2], rotation: [90, 0, 0], scale: [0.4, 1, 0.4], material: matte([0.9, 0.6, 0.2]) },
        { id: 'far', shape: 'sphere', position: [0.5, 0.3, -6], material: matte([0.2, 0.5, 0.9]) },
      ],
      lights: [pointLight([0, 0, 0])],
    });
    const pinhole = render(file(0), 60);
    for (const aperture of [0.05, 0.2, 0.5]) {
      const lens = render(file(aperture), 60);
      let cardPixels = 0;
      let farDifference = 0;
      for (let i = 0; i < pinhole.length; i += 3) {
        const onCard = pinhole[i] > 0.5; // the card is orange: red 0.9·shading; the far ball's red is 0.2·shading
        if (onCard) {
          cardPixels++;
          for (let c = 0; c < 3; c++) expect(Math.abs(lens[i + c] - pinhole[i + c])).toBeLessThan(1e-6);
        } else farDifference = Math.max(farDifference, Math.abs(lens[i + 2] - pinhole[i + 2]));
      }
      expect(cardPixels).toBeGreaterThan(200);
      // Off the plane the lens does blur: the far ball's edge changes.
      expect(farDifference).toBeGreaterThan(0.1);
    }
  });

  it('every lens ray of a pixel meets the pinhole ray on the plane in focus', () => {
    const scene = tracerSceneFrom(pointScene(4, 0.3, 2.5, 0.02));
    const [root] = tracePixel(scene, 3, 1, 1).rays;
    const focal = root.origin.map((c, i) => c + root.direction[i] * root.length);
    // The plane in focus is z = −2.5 (the camera looks down −z).
    expect(focal[2]).toBeCloseTo(-2.5, 12);
    expect(root.children).toHaveLength(64);
    for (const ray of root.children) {
      const t = (focal[2] - ray.origin[2]) / ray.direction[2];
      for (let axis = 0; axis < 3; axis++) expect(ray.origin[axis] + t * ray.direction[axis]).toBeCloseTo(focal[axis], 12);
    }
  });

  // The thin-lens circle of confusion (Potmesil & Chakravarty, "A Lens and Aperture Camera
  // Model for Synthetic Image Generation", SIGGRAPH 1981): a point at depth z seen through a
  // lens of radius a focused at f is spread, on the plane in focus, over a disc of radius
  // R = a·|z − f|/z. A ball of radius r there has radius ρ = r·f/z, and a uniform disc of
  // radius R smeared over it has σ² = (R² + ρ²)/4 along any axis.
  for (const [z, f, a] of [
    [4, 2, 0.1],
    [4, 2, 0.2],
    [1.5, 3, 0.1],
  ]) {
    it(`the circle of confusion has radius a·|z − f|/z (z = ${z}, f = ${f}, a = ${a})`, () => {
      const r = 0.02;
      const pixelsPerMetre = SIZE / (2 * f * Math.tan((FOV / 2) * (Math.PI / 180)));
      const R = ((a * Math.abs(z - f)) / z) * pixelsPerMetre;
      const rho = ((r * f) / z) * pixelsPerMetre;
      const measured = spread(render(pointScene(z, a, f, r)), SIZE);
      expect(measured.sigma).toBeGreaterThan(0.95 * Math.sqrt((R * R + rho * rho) / 4));
      expect(measured.sigma).toBeLessThan(1.05 * Math.sqrt((R * R + rho * rho) / 4));
      expect(measured.reach).toBeLessThan(R + rho + 1);
      expect(measured.reach).toBeGreaterThan(R + rho - 2);
      // The pinhole shows the ball alone.
      expect(spread(render(pointScene(z, 0, f, r)), SIZE).reach).toBeLessThan(rho + 1);
    });
  }
});
