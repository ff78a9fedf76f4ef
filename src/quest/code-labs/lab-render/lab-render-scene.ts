import type { Material, Scene, SceneObject } from '../../../scene/scene.ts';
import { buildTracerScene, type TracerScene } from '../../../tracer/tracer-scene.ts';
import type { PhongLight } from '../phong-lab.ts';
import type { Sphere } from '../shadow-lab.ts';
import { v } from '../lab-vectors.ts';

/** A sphere of the scene as the labs see it (a centre and a radius), with its material. */
export interface LabSphere extends Sphere {
  material: Material;
}

/** A light as the Phong lab sees it, with its own ambient factor la. */
export interface LabLight extends PhongLight {
  ambient: number;
}

/** A level's scene prepared for a lab render: its spheres for the labs' functions, the rest for the tracer's shapes. */
export interface LabRenderScene {
  readonly source: Scene;
  /** Every object that is not a lab sphere (planes, boxes, cylinders, ellipsoids), intersected by the tracer's own shapes. */
  readonly others: TracerScene;
  readonly spheres: readonly LabSphere[];
  readonly lights: readonly LabLight[];
}

/** A sphere the ray–sphere lab's contract covers: scaled alike on every axis (an ellipsoid is not a sphere) and not moving. */
const isLabSphere = (object: SceneObject) =>
  object.shape === 'sphere' && object.scale.every((s) => s === object.scale[0]) && object.velocity.every((component) => component === 0);

/**
 * The tracer's unit sphere has radius 0.5 (shapes/sphere.ts), so a sphere scaled by s has
 * radius s/2. Meshes are left out: a lab render does not load models. Every light counts as
 * a point light at its position (the Phong lab's light), when its type is switched on.
 */
export function labRenderScene(scene: Scene): LabRenderScene {
  const spheres = scene.objects
    .filter(isLabSphere)
    .map((object): LabSphere => ({ center: v(...object.position), radius: object.scale[0] / 2, material: object.material }));
  const others = scene.objects.filter((object) => !isLabSphere(object) && object.shape !== 'mesh');
  const enabled = scene.settings.lightTypes;
  const lights = scene.lights
    .filter((light) => enabled[light.type])
    .map((light): LabLight => ({
      position: v(...light.position),
      color: { r: light.color[0], g: light.color[1], b: light.color[2] },
      intensity: light.intensity,
      ambient: light.ambient,
    }));
  return { source: scene, others: buildTracerScene({ ...scene, objects: others }, new Map()), spheres, lights };
}
