import { describe, expect, it } from 'vitest';
import { defaultScene } from '../../src/scene/scene-defaults.ts';
import type { Scene } from '../../src/scene/scene.ts';
import { interned } from '../../src/tracer/interned.ts';
import { renderTile } from '../../src/tracer/render-tile.ts';
import { buildTracerScene } from '../../src/tracer/tracer-scene.ts';

const KINDS = { grid: 'grid', jittered: 'jittered' } as const;

describe('interned', () => {
  it("gives the table's constant for a name it holds, and any other string back as it is", () => {
    expect(interned(['gr', 'id'].join('') as 'grid', KINDS)).toBe('grid');
    expect(interned('random' as 'grid', KINDS)).toBe('random');
    // Names inherited by every object are not constants of the table.
    expect(interned('toString' as 'grid', KINDS)).toBe('toString');
  });
});

describe("a scene that came through postMessage (a render worker's)", () => {
  it('keeps every setting and renders the same picture as the scene it was copied from', () => {
    const scene: Scene = { ...defaultScene(), settings: { ...defaultScene().settings, samplePattern: 'jittered', supersampling: 2 } };
    const received = structuredClone(scene);
    const options = { imageWidth: 24, imageHeight: 16, seed: 3 };
    const tile = { x: 0, y: 0, width: 24, height: 16 };

    expect(buildTracerScene(received, new Map()).settings).toEqual(scene.settings);
    expect(renderTile(buildTracerScene(received, new Map()), tile, options)).toEqual(renderTile(buildTracerScene(scene, new Map()), tile, options));
  });
});
