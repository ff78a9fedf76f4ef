import type { Material } from '../../../scene/scene.ts';

/** A finish the object panel can apply in one step: every material field but the colour. */
export type MaterialFinish = Omit<Material, 'color'>;

/**
 * The object panel's presets. They keep the object's colour (a red mirror stays red) and
 * set the rest at once, in one `material.changed`, so a level can wait for "glass" as one
 * event. The values are the default scene's three spheres (scene-defaults.ts), so a preset
 * looks like what the student has already seen; Opaque is the schema's default material.
 */
export const MATERIAL_PRESETS = {
  opaque: { ambient: 0.2, diffuse: 1, specular: 0, shininess: 32, transparent: false, refractiveIndex: 1.5, roughness: 0, glossySamples: 3 },
  mirror: { ambient: 0.05, diffuse: 0.1, specular: 0.85, shininess: 200, transparent: false, refractiveIndex: 1.5, roughness: 0, glossySamples: 3 },
  glass: { ambient: 0, diffuse: 0.05, specular: 0.6, shininess: 200, transparent: true, refractiveIndex: 1.5, roughness: 0, glossySamples: 3 },
} as const satisfies Record<string, MaterialFinish>;

export type MaterialPresetName = keyof typeof MATERIAL_PRESETS;

/** The preset whose finish `material` has, if any (shown as the pressed preset button). */
export function matchingPreset(material: Material): MaterialPresetName | undefined {
  const names = Object.keys(MATERIAL_PRESETS) as MaterialPresetName[];
  return names.find((name) =>
    (Object.entries(MATERIAL_PRESETS[name]) as [keyof MaterialFinish, number | boolean][]).every(([field, value]) => material[field] === value),
  );
}
