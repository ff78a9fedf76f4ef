import { Group, PerspectiveCamera, Scene as ThreeScene, type WebGLRenderer } from 'three';
import { describe, expect, it } from 'vitest';
import { defaultScene } from '../../src/scene/scene-defaults.ts';
import type { RayLayer } from '../../src/view/ray-layer.ts';
import { type ProbedView, ViewProbes } from '../../src/view/view-probes.ts';

/**
 * A drawing buffer of 4 × 4 device pixels at 2 per CSS pixel (a 2 × 2 canvas): one buffer
 * pixel changes by white when the rays and a code lab's case are drawn, another by 8 on each
 * of R, G and B.
 */
function drawnTwice() {
  const width = 4;
  const height = 4;
  const layer = { object: new Group() } as unknown as RayLayer;
  const caseLayer = new Group();
  let renders = 0;
  let requested = 0;
  const gl = {
    drawingBufferWidth: width,
    drawingBufferHeight: height,
    RGBA: 0,
    UNSIGNED_BYTE: 0,
    readPixels: (_x: number, _y: number, w: number, _h: number, _format: number, _type: number, pixels: Uint8Array) => {
      if (!layer.object.visible || !caseLayer.visible) return;
      // Buffer rows run bottom-up: row 3 is the canvas's top, row 1 its bottom half.
      pixels.set([255, 255, 255], (3 * w + 0) * 4);
      pixels.set([8, 8, 8], (1 * w + 2) * 4);
    },
  };
  const renderer = { getContext: () => gl, render: () => renders++, getPixelRatio: () => 2 } as unknown as WebGLRenderer;
  const view: ProbedView = {
    renderer,
    scene: new ThreeScene(),
    camera: new PerspectiveCamera(),
    rayLayer: () => layer,
    caseLayer,
    allRaysDrawn: () => false,
    idle: () => true,
    traceOf: () => null,
    framedPointsOf: () => [
      [0, 0, 0],
      [1, 0, 0],
    ],
    projectToView: ([x]) => (x > 0 ? null : { x: 10, y: 20 }),
    opaque: new Group(),
    requestRender: () => requested++,
  };
  return { probes: new ViewProbes(view), layer, caseLayer, renders: () => renders, requested: () => requested };
}

describe('the 3D view probes for browser tests', () => {
  it('know no drawn scene before a frame, and the scenes of the last frame after', () => {
    const { probes } = drawnTwice();
    expect(probes.drawnScene).toBeNull();
    expect(probes.drawnRaysScene).toBeNull();
    const scene = defaultScene();
    const traced = defaultScene();
    probes.frameDrawn(scene, traced);
    expect(probes.drawnScene).toBe(scene);
    expect(probes.drawnRaysScene).toBe(traced);
    probes.frameDrawn(traced, null);
    expect(probes.drawnScene).toBe(traced);
    expect(probes.drawnRaysScene).toBeNull();
  });

  it('mark a CSS pixel as covered by rays where drawing them changed it by more than a little, top row first', () => {
    const { probes, layer, renders, requested } = drawnTwice();
    const coverage = probes.rayCoverage();
    expect(coverage.width).toBe(2);
    expect(coverage.height).toBe(2);
    // Top-left changed by white; bottom-right by 24 in all, which is not more than the threshold.
    expect([...coverage.mask]).toEqual([1, 0, 0, 0]);
    expect(renders()).toBe(2);
    expect(layer.object.visible).toBe(true);
    expect(requested()).toBe(1);
  });

  it('mark where a code lab’s case shows the same way, and nothing while no case is shown', () => {
    const { probes, caseLayer, renders } = drawnTwice();
    expect([...probes.caseCoverage().mask]).toEqual([1, 0, 0, 0]);
    expect(caseLayer.visible).toBe(true);
    caseLayer.visible = false;
    expect([...probes.caseCoverage().mask]).toEqual([0, 0, 0, 0]);
    expect(caseLayer.visible).toBe(false);
    expect(renders()).toBe(4);
  });

  it("project a declared view's points, null behind the eye, and say whether all rays were drawn", () => {
    const { probes } = drawnTwice();
    expect(probes.projectedPointsOf('ball')).toEqual([{ x: 10, y: 20 }, null]);
    expect(probes.raysComplete).toBe(false);
    expect(probes.evidenceRay([0, 0], 'primary')).toBeNull();
  });
});
