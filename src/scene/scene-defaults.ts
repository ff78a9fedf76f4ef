import type { z } from 'zod';
import type { Light, LightType, Scene, SceneObject, ShapeKind } from './scene.ts';
import type { LocalizedText } from '../util/localized-text.ts';
import { footprintRadius, freePlace } from './free-place.ts';
import { MESH_ASSET_NAMES, type MeshAssetName } from './mesh-assets.ts';
import { lightSchema, sceneObjectSchema, sceneSchema } from './scene-schema.ts';

/**
 * Ready-made scenes and scene parts. Everything left out here is filled in by the schema's
 * defaults, so each default value is written down in one place only (scene-schema.ts).
 */

/** Clear glass (n = 1.5, as window glass): the default scene's glass ball, and models of glass. */
const CLEAR_GLASS = { ambient: 0, diffuse: 0.05, specular: 0.6, shininess: 200, transparent: true, refractiveIndex: 1.5 };

/** The models that are made of glass, and come into a scene as glass. */
const GLASS_MODELS: ReadonlySet<MeshAssetName> = new Set(['wine-glass']);

/**
 * The scene the lab opens with: one of each kind of material (diffuse, mirror, glass) on a
 * floor, a box for hard edges, a point light for shadows and a spot light for its cone. Its
 * names are in both languages (the scene list shows a name, else the id).
 */
export function defaultScene(): Scene {
  const scene: z.input<typeof sceneSchema> = {
    version: 1,
    name: { en: 'Three spheres and a box', nl: 'Drie bollen en een doos' },
    objects: [
      { id: 'floor', name: { en: 'Floor', nl: 'Vloer' }, shape: 'plane', scale: [10, 1, 10], material: { color: [0.7, 0.7, 0.7] } },
      { id: 'red-ball', name: { en: 'Red ball', nl: 'Rode bal' }, shape: 'sphere', position: [-1.5, 0.5, 0.3], material: { color: [0.9, 0.15, 0.1] } },
      {
        id: 'mirror-ball',
        name: { en: 'Mirror ball', nl: 'Spiegelbal' },
        shape: 'sphere',
        position: [0.2, 0.5, -1],
        material: { color: [0.9, 0.9, 0.9], ambient: 0.05, diffuse: 0.1, specular: 0.85, shininess: 200 },
      },
      {
        id: 'glass-ball',
        name: { en: 'Glass ball', nl: 'Glazen bal' },
        shape: 'sphere',
        position: [1, 0.5, 1.2],
        material: { ...CLEAR_GLASS },
      },
      {
        id: 'box',
        name: { en: 'Box', nl: 'Doos' },
        shape: 'box',
        position: [-0.8, 0.35, -2.4],
        rotation: [0, 30, 0],
        scale: [0.7, 0.7, 0.7],
        material: { color: [0.2, 0.4, 0.9] },
      },
    ],
    lights: [
      { id: 'lamp', name: { en: 'Lamp', nl: 'Lamp' }, type: 'point', position: [2, 4, 3], intensity: 0.7 },
      // No ambient of its own: the lamp's already lights the shadows.
      { id: 'spot', name: { en: 'Spot', nl: 'Spot' }, type: 'spot', position: [-1.5, 3, 0.3], ambient: 0, intensity: 0.35, spotAngle: 40 },
    ],
  };
  return sceneSchema.parse(scene);
}

/**
 * What a new object or light is called in the scene list, in both languages, before its
 * number: a Dutch pupil who adds a sphere reads "Bol 1", not its id "sphere-1".
 */
const NEW_ITEM_NAMES: Record<ShapeKind | LightType, { en: string; nl: string }> = {
  sphere: { en: 'Sphere', nl: 'Bol' },
  box: { en: 'Box', nl: 'Doos' },
  cylinder: { en: 'Cylinder', nl: 'Cilinder' },
  plane: { en: 'Plane', nl: 'Vlak' },
  mesh: { en: 'Model', nl: 'Model' },
  point: { en: 'Point light', nl: 'Puntlamp' },
  spot: { en: 'Spot light', nl: 'Spotlamp' },
  area: { en: 'Area light', nl: 'Vlaklamp' },
};

/**
 * A new object of this shape (a mesh: of model `mesh`, by default the first) with every
 * default, with an id unused in `scene`. It stands on the floor (y = 0) at the free place
 * nearest to where the camera looks, not inside what is there already; a model of glass (the
 * wine glass) comes as clear glass.
 */
export function createObject(shape: ShapeKind, scene: Scene, mesh?: string): SceneObject {
  // Only a mesh has the `mesh` field at all (even `mesh: undefined` would show up as a key).
  // An unknown model name is kept as asked: the scene's schema refuses it with its reason.
  const model = shape === 'mesh' ? { mesh: MESH_ASSET_NAMES[0] } : {};
  const glass = shape === 'mesh' && GLASS_MODELS.has((mesh ?? MESH_ASSET_NAMES[0]) as MeshAssetName) ? { material: { ...CLEAR_GLASS } } : {};
  const object: SceneObject = sceneObjectSchema.parse({ ...newItem(shape, scene), shape, ...model, ...glass });
  if (shape === 'mesh' && mesh !== undefined) object.mesh = mesh;
  const [x, z] = freePlace(scene.objects, footprintRadius(object), scene.camera.target);
  // A plane lies just above a floor at y = 0 rather than in it; a unit shape's base is 0.5 below its centre.
  object.position = [x, shape === 'plane' ? 0.01 : 0.5 * object.scale[1], z];
  return object;
}

/** A new light of this type with every default, 3 m above the origin, with an id unused in `scene`. */
export function createLight(type: LightType, scene: Scene): Light {
  return lightSchema.parse({ ...newItem(type, scene), type });
}

/** `sphere-1` named "Sphere 1" / "Bol 1", `sphere-2`, …: the first id not taken by an object or a light. */
function newItem(kind: ShapeKind | LightType, scene: Scene): { id: string; name: LocalizedText } {
  const taken = new Set([...scene.objects, ...scene.lights].map((item) => item.id));
  let number = 1;
  while (taken.has(`${kind}-${number}`)) number++;
  const { en, nl } = NEW_ITEM_NAMES[kind];
  return { id: `${kind}-${number}`, name: { en: `${en} ${number}`, nl: `${nl} ${number}` } };
}
