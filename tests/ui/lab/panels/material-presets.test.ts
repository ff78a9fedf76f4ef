import { expect, test } from 'vitest';
import { MATERIAL_PRESETS, matchingPreset } from '../../../../src/ui/lab/panels/material-presets.ts';
import { createObject, defaultScene } from '../../../../src/scene/scene-defaults.ts';
import type { Material } from '../../../../src/scene/scene.ts';

/** A material without its colour (presets keep the colour). */
function finish({ color: _color, ...rest }: Material) {
  return rest;
}

test('Opaque is the default material, Mirror and Glass are the default scene’s spheres', () => {
  const scene = defaultScene();
  const material = (id: string) => scene.objects.find((o) => o.id === id)!.material;
  expect(MATERIAL_PRESETS.opaque).toEqual(finish(createObject('sphere', scene).material));
  expect(MATERIAL_PRESETS.mirror).toEqual(finish(material('mirror-ball')));
  expect(MATERIAL_PRESETS.glass).toEqual(finish(material('glass-ball')));
});

test('matchingPreset finds the preset a material has, whatever its colour', () => {
  const scene = defaultScene();
  const material = (id: string) => scene.objects.find((o) => o.id === id)!.material;
  expect(matchingPreset(material('red-ball'))).toBe('opaque');
  expect(matchingPreset(material('mirror-ball'))).toBe('mirror');
  expect(matchingPreset({ ...material('glass-ball'), color: [0.2, 0.9, 0.3] })).toBe('glass');
  expect(matchingPreset({ ...material('glass-ball'), refractiveIndex: 1.33 })).toBeUndefined();
});
