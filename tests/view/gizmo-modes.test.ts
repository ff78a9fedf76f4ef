import { describe, expect, it } from 'vitest';
import { createLight, defaultScene } from '../../src/scene/scene-defaults.ts';
import { effectiveGizmoMode, gizmoModesFor } from '../../src/view/gizmo-modes.ts';

describe('gizmo modes per selection', () => {
  const scene = defaultScene();
  scene.lights.push(createLight('area', scene));

  it('offers what makes sense: objects and area lights all three, spots and the camera no scale, a point light only moves', () => {
    expect(gizmoModesFor({ kind: 'object', id: 'box' }, scene)).toEqual(['translate', 'rotate', 'scale']);
    expect(gizmoModesFor({ kind: 'light', id: 'lamp' }, scene)).toEqual(['translate']);
    expect(gizmoModesFor({ kind: 'light', id: 'spot' }, scene)).toEqual(['translate', 'rotate']);
    expect(gizmoModesFor({ kind: 'light', id: 'area-1' }, scene)).toEqual(['translate', 'rotate', 'scale']);
    expect(gizmoModesFor({ kind: 'camera' }, scene)).toEqual(['translate', 'rotate']);
    expect(gizmoModesFor(null, scene)).toEqual([]);
  });

  it('falls back to moving when the chosen mode does not apply', () => {
    expect(effectiveGizmoMode('scale', ['translate', 'rotate'])).toBe('translate');
    expect(effectiveGizmoMode('rotate', ['translate', 'rotate'])).toBe('rotate');
  });
});
