import type { Material, Scene, SceneObject } from '../../../scene/scene.ts';
import { buildTracerScene, type TracerScene } from '../../../tracer/tracer-scene.ts';
import type { PhongLight } from '../phong-lab.ts';
import type { Sphere } from '../shadow-lab.ts';
import type { Vec3 } from '../code-lab-grading.ts';
import { v } from '../lab-vectors.ts';

/** A sphere of the scene as the labs see it (a centre and a radius), with its material. */
export interface LabSphere extends Sphere {
  material: Material;
}

/** An axis-aligned box of the scene as the box lab sees it (its min and max corners), with its material. */
export interface LabBox {
  min: Vec3;
  max: Vec3;
  material: Material;
}

/** A light as the Phong lab sees it, with its own ambient factor la. */
export interface LabLight extends PhongLight {
  ambient: number;
}

/** A level's scene prepared for a lab render: its spheres for the labs' functions, the rest for the tracer's shapes. */
export interface LabRenderScene {
  readonly source: Scene;
  /** Every object that is not a lab sphere or box (planes, rotated boxes, cylinders, ellipsoids), intersected by the tracer's own shapes. */
  readonly others: TracerScene;
  readonly spheres: readonly LabSphere[];
  readonly boxes: readonly LabBox[];
  readonly lights: readonly LabLight[];
}

/** A sphere the ray–sphere lab's contract covers: scaled alike on every axis (an ellipsoid is not a sphere) and not moving. */
const isLabSphere = (object: SceneObject) => object.shape === 'sphere' && object.scale.every((s) => s === object.scale[0]) && still(object);

const still = (object: SceneObject) => object.velocity.every((component) => component === 0);

/** A box the box lab's contract covers: not turned (its faces along the axes) and not moving. */
const isLabBox = (object: SceneObject) => object.shape === 'box' && object.rotation.every((angle) => angle === 0) && still(object);

/**
 * The tracer's unit sphere has radius 0.5 (shapes/sphere.ts), so a sphere scaled by s has
 * radius s/2; its unit cube spans −0.5 to 0.5 (shapes/box.ts), so a box scaled by s spans
 * its position ± s/2 on each axis. Meshes are left out: a lab render does not load models. Every light counts as
 * a point light at its position (the Phong lab's light), when its type is switched on.
 */
export function labRenderScene(scene: Scene): LabRenderScene {
  const spheres = scene.objects
    .filter(isLabSphere)
    .map((object): LabSphere => ({ center: v(...object.position), radius: object.scale[0] / 2, material: object.material }));
  const boxes = scene.objects.filter(isLabBox).map((object): LabBox => {
    const [x, y, z] = object.position;
    const [sx, sy, sz] = object.scale;
    return { min: v(x - sx / 2, y - sy / 2, z - sz / 2), max: v(x + sx / 2, y + sy / 2, z + sz / 2), material: object.material };
  });
  const others = scene.objects.filter((object) => !isLabSphere(object) && !isLabBox(object) && object.shape !== 'mesh');
  const enabled = scene.settings.lightTypes;
  const lights = scene.lights
    .filter((light) => enabled[light.type])
    .map((light): LabLight => ({
      position: v(...light.position),
      color: { r: light.color[0], g: light.color[1], b: light.color[2] },
      intensity: light.intensity,
      ambient: light.ambient,
    }));
  return { source: scene, others: buildTracerScene({ ...scene, objects: others }, new Map()), spheres, boxes, lights };
}
