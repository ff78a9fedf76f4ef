import { DataTexture, Mesh, type MeshBasicMaterial, Points, Vector3 } from 'three';
import { describe, expect, it } from 'vitest';
import type { Camera } from '../../src/scene/scene.ts';
import type { PixelTrace } from '../../src/tracer/ray-tree.ts';
import { CameraScreen, type CameraScreenState } from '../../src/view/camera-screen.ts';
import { screenGrid } from '../../src/view/screen-grid.ts';

const camera: Camera = { position: [0, 1, 5], target: [0, 0.5, 0], fov: 45, pixels: [4, 3], screenDistance: 1, aperture: 0, lensSamples: 1 };

function state(changes: Partial<CameraScreenState> = {}): CameraScreenState {
  return { camera, settings: { supersampling: 1, samplePattern: 'grid' }, selectedPixel: null, showSamplePoints: false, ...changes };
}

function screenTexture(screen: CameraScreen): DataTexture {
  let texture: DataTexture | null = null;
  screen.rig.traverse((node) => {
    const map = node instanceof Mesh ? (node.material as MeshBasicMaterial).map : null;
    if (map instanceof DataTexture) texture = map;
  });
  return texture!;
}

function traces(columns: number, rows: number, color: (x: number, y: number) => [number, number, number]): PixelTrace[] {
  const all: PixelTrace[] = [];
  for (let y = 0; y < rows; y++) for (let x = 0; x < columns; x++) all.push({ pixel: [x, y], color: color(x, y), rays: [] });
  return all;
}

describe('the camera and its screen', () => {
  it('sits at the camera’s eye looking at its target', () => {
    const screen = new CameraScreen();
    screen.sync(state());
    expect(screen.rig.position.toArray()).toEqual([0, 1, 5]);
    const forward = new Vector3(0, 0, -1).applyQuaternion(screen.rig.quaternion);
    expect(forward.distanceTo(new Vector3(0, -0.5, -5).normalize())).toBeLessThan(1e-9);
  });

  it('shows pixel (x, y) in the texel the quad maps to it (texture rows bottom-up), quantized like the render', () => {
    const screen = new CameraScreen();
    screen.sync(state());
    screen.setScreenRays({ columns: 4, rows: 3, traces: traces(4, 3, (x, y) => [x / 3, y / 2, 1.7]) });
    const texture = screenTexture(screen);
    expect([texture.image.width, texture.image.height]).toEqual([4, 3]);
    const data = texture.image.data as Uint8Array;
    const texel = (x: number, y: number) => Array.from(data.slice(((2 - y) * 4 + x) * 4, ((2 - y) * 4 + x) * 4 + 4));
    expect(texel(0, 0)).toEqual([0, 0, 255, 255]);
    expect(texel(3, 0)).toEqual([255, 0, 255, 255]);
    expect(texel(1, 2)).toEqual([Math.round(255 / 3), 255, 255, 255]);
  });

  it('ignores traces made for another screen size (a late answer after the pixels changed)', () => {
    const screen = new CameraScreen();
    screen.sync(state({ camera: { ...camera, pixels: [2, 2] } }));
    const before = Array.from(screenTexture(screen).image.data as Uint8Array);
    screen.setScreenRays({ columns: 4, rows: 3, traces: traces(4, 3, () => [1, 1, 1]) });
    expect(Array.from(screenTexture(screen).image.data as Uint8Array)).toEqual(before);
  });

  it('makes a new texture only when the number of pixels changes', () => {
    const screen = new CameraScreen();
    screen.sync(state());
    const first = screenTexture(screen);
    screen.sync(state({ camera: { ...camera, fov: 60, screenDistance: 2 } }));
    expect(screenTexture(screen)).toBe(first);
    screen.sync(state({ camera: { ...camera, pixels: [16, 9] } }));
    expect([screenTexture(screen).image.width, screenTexture(screen).image.height]).toEqual([16, 9]);
  });

  it('outlines the selected pixel’s cell, and nothing when none is selected', () => {
    const screen = new CameraScreen();
    screen.sync(state({ selectedPixel: [3, 0] }));
    const frame = screen.rig.children.flatMap((child) => child.children).find((node) => node instanceof Mesh && node.scale.x === 1 / 4)!;
    expect(frame.visible).toBe(true);
    // The top-right cell's centre, in the screen quad's unit coordinates.
    expect(frame.position.x).toBeCloseTo(0.375, 12);
    expect(frame.position.y).toBeCloseTo(1 / 3, 12);
    screen.sync(state());
    expect(frame.visible).toBe(false);
  });

  it('shows s×s sample points per pixel only when asked, on the screen plane', () => {
    const screen = new CameraScreen();
    const points = screen.rig.children.find((child) => child instanceof Points) as Points;
    screen.sync(state({ settings: { supersampling: 3, samplePattern: 'jittered' } }));
    expect(points.visible).toBe(false);
    screen.sync(state({ settings: { supersampling: 3, samplePattern: 'jittered' }, showSamplePoints: true }));
    expect(points.visible).toBe(true);
    const position = points.geometry.getAttribute('position');
    expect(position.count).toBe(4 * 3 * 9);
    const grid = screenGrid(camera);
    for (let i = 0; i < position.count; i++) {
      expect(Math.abs(position.getX(i))).toBeLessThanOrEqual(grid.halfWidth);
      expect(Math.abs(position.getY(i))).toBeLessThanOrEqual(grid.halfHeight);
      expect(position.getZ(i)).toBeCloseTo(-1, 6);
    }
  });
});
