import { type Color, DoubleSide, FrontSide, type MeshPhongMaterial } from 'three';
import type { Color as RgbColor, Material, Scene } from '../scene/scene.ts';

/** A glass object is drawn see-through at this opacity: a raster cannot refract. */
export const TRANSPARENT_OPACITY = 0.35;

/**
 * The ambient light the ray tracer adds to every surface, Σ la·Lc over the switched-on
 * lights (spec §2): the raster view adds it through the material's emissive colour, since
 * three.js's ambient light would be scaled by the diffuse coefficient and by 1/π.
 */
export function ambientLight(scene: Scene, out: Color): Color {
  out.setRGB(0, 0, 0);
  const enabled = scene.settings.lightTypes;
  for (const light of scene.lights) {
    if (!enabled[light.type]) continue;
    out.r += light.ambient * light.color[0];
    out.g += light.ambient * light.color[1];
    out.b += light.ambient * light.color[2];
  }
  return out;
}

/**
 * Phong in three.js terms (spec §2 with three.js's conventions): the diffuse colour is kd·C,
 * specular ks (white, not tinted by C), the exponent n, and the ambient part
 * C·(ka + Σ la·Lc) as emissive. Edits values in place: a slider drag allocates nothing.
 */
export function applyRasterMaterial(target: MeshPhongMaterial, material: Material, ambient: Color, doubleSided: boolean): void {
  const [r, g, b] = material.color;
  target.color.setRGB(r * material.diffuse, g * material.diffuse, b * material.diffuse);
  target.specular.setRGB(material.specular, material.specular, material.specular);
  target.shininess = material.shininess;
  setEmissive(target.emissive, material.color, material.ambient, ambient);
  const side = doubleSided ? DoubleSide : FrontSide;
  // Sidedness and opacity are compiled into the shader (DOUBLE_SIDED, OPAQUE defines).
  if (target.side !== side || target.transparent !== material.transparent) target.needsUpdate = true;
  target.side = side;
  target.transparent = material.transparent;
  target.opacity = material.transparent ? TRANSPARENT_OPACITY : 1;
  // A see-through surface must not hide what is behind it from the depth test.
  target.depthWrite = !material.transparent;
}

function setEmissive(out: Color, color: RgbColor, ka: number, ambient: Color): void {
  out.setRGB(Math.min(1, color[0] * (ka + ambient.r)), Math.min(1, color[1] * (ka + ambient.g)), Math.min(1, color[2] * (ka + ambient.b)));
}
