import { Box3, Matrix4, Vector3 } from 'three';
import type { MeshLibrary } from '../scene/mesh-data.ts';
import type { BounceSampling, RenderSettings, SamplePattern, Scene, SceneObject, ShapeKind } from '../scene/scene.ts';
import { CameraRays } from './camera-rays.ts';
import type { Intersectable } from './intersectable.ts';
import { interned } from './interned.ts';
import { TracerLight } from './lights.ts';
import { tracerMaterial } from './tracer-material.ts';
import { ObjectBvh } from './object-bvh.ts';
import { meshAccel } from './shapes/mesh-accel.ts';
import { Shape } from './shapes/shape.ts';
import { sceneQuaternion } from './scene-rotation.ts';

/** The shape kinds, sample (and time) patterns and path mode's bounce sampling the tracer compares in its hot code, kept as this program's own constants (see interned.ts). */
const SHAPE_KINDS: { readonly [K in ShapeKind]: K } = { sphere: 'sphere', box: 'box', cylinder: 'cylinder', plane: 'plane', mesh: 'mesh' };
const SAMPLE_PATTERNS: { readonly [K in SamplePattern]: K } = { grid: 'grid', jittered: 'jittered', random: 'random' };
const BOUNCE_SAMPLINGS: { readonly [K in BounceSampling]: K } = { cosine: 'cosine', uniform: 'uniform' };

/** Everything the tracer needs, prepared once per scene (and reused for every tile). */
export interface TracerScene {
  readonly source: Scene;
  readonly settings: RenderSettings;
  readonly camera: CameraRays;
  readonly shapes: readonly Intersectable[];
  /** A BVH over the shapes, for nearest hits. */
  readonly objects: ObjectBvh;
  /** BVHs over the cheap analytic shapes, then over the meshes: the order shadow rays try them in. */
  readonly occluders: readonly ObjectBvh[];
  /** The lights whose type is switched on in settings.lightTypes. */
  readonly lights: readonly TracerLight[];
  /** How far secondary rays start off a surface: 1e-4, scaled up for large scenes. */
  readonly epsilon: number;
  /** Time spent building mesh BVHs for this scene (0 when all were cached). */
  readonly bvhBuildMs: number;
}

/** Prepares a validated scene for tracing. Throws if a mesh object's model is missing. */
export function buildTracerScene(scene: Scene, meshes: MeshLibrary): TracerScene {
  const started = performance.now();
  const shapes = scene.objects.map((object, index) => createShape(object, index, meshes));
  const bvhBuildMs = performance.now() - started;
  const extent = new Box3();
  for (const shape of shapes) extent.union(shape.worldBounds);
  // The diagonal of the objects' bounds (1 for a scene without objects).
  const size = extent.isEmpty() ? 1 : extent.getSize(new Vector3()).length();
  const enabled = scene.settings.lightTypes;
  return {
    source: scene,
    settings: {
      ...scene.settings,
      samplePattern: interned(scene.settings.samplePattern, SAMPLE_PATTERNS),
      timePattern: interned(scene.settings.timePattern, SAMPLE_PATTERNS),
      bounceSampling: interned(scene.settings.bounceSampling, BOUNCE_SAMPLINGS),
    },
    camera: new CameraRays(scene.camera),
    shapes,
    ...objectBvhs(shapes),
    lights: scene.lights.filter((light) => enabled[light.type]).map((light) => new TracerLight(light)),
    epsilon: 1e-4 * Math.max(1, size / 10),
    bvhBuildMs,
  };
}

/** The object BVHs of a scene's shapes (the benchmark's naive tracer builds its own). */
export function objectBvhs(shapes: readonly Intersectable[]): Pick<TracerScene, 'objects' | 'occluders'> {
  return {
    objects: new ObjectBvh(shapes),
    occluders: [new ObjectBvh(shapes.filter((s) => s.convex)), new ObjectBvh(shapes.filter((s) => !s.convex))],
  };
}

function createShape(object: SceneObject, index: number, meshes: MeshLibrary): Shape {
  const toWorld = objectToWorld(object);
  const moves = object.velocity.some((component) => component !== 0);
  const velocity = moves ? new Vector3(...object.velocity) : null;
  if (object.shape !== 'mesh')
    return new Shape(index, object.id, tracerMaterial(object.material), interned(object.shape, SHAPE_KINDS), toWorld, null, velocity);
  const mesh = object.mesh === undefined ? undefined : meshes.get(object.mesh);
  if (!mesh) throw new Error(`objects[${index}] ("${object.id}"): the model "${object.mesh}" was not loaded`);
  return new Shape(index, object.id, tracerMaterial(object.material), 'mesh', toWorld, meshAccel(mesh), velocity);
}

/** position · rotation (scene-rotation.ts) · scale, as three.js composes an Object3D. */
export function objectToWorld(object: Pick<SceneObject, 'position' | 'rotation' | 'scale'>): Matrix4 {
  return new Matrix4().compose(new Vector3(...object.position), sceneQuaternion(object.rotation), new Vector3(...object.scale));
}
