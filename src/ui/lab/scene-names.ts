import { msg } from '@lit/localize';
import type { LightType, Scene, SceneObject, ShapeKind } from '../../scene/scene.ts';
import { localize, type LocalizedText } from '../../util/localized-text.ts';
import { currentLocale } from '../../i18n/locale.ts';
import { MESH_ASSET_NAMES, type MeshAssetName } from '../../scene/mesh-assets.ts';

/** The words the panels use for shapes, models and light types (translated, unlike ids), and the scene's own names. */

/** A scene's, an object's or a light's name in the app's language ("Rode bal"), or `fallback` (its id) when it has none. */
export function shownName(name: LocalizedText | undefined, fallback: string): string {
  return name === undefined ? fallback : localize(name, currentLocale());
}

/** The name of the object or light with this id, as the scene list shows it; the id itself when nothing has it. */
export function itemName(scene: Scene, id: string): string {
  const item = scene.objects.find((object) => object.id === id) ?? scene.lights.find((light) => light.id === id);
  return shownName(item?.name, id);
}

export function shapeKindName(shape: Exclude<ShapeKind, 'mesh'>): string {
  switch (shape) {
    case 'sphere':
      return msg('Sphere');
    case 'box':
      return msg('Box');
    case 'cylinder':
      return msg('Cylinder');
    case 'plane':
      return msg('Plane');
  }
}

export function modelName(mesh: MeshAssetName): string {
  switch (mesh) {
    case 'prism':
      return msg('Prism');
    case 'capsule':
      return msg('Capsule');
    case 'wine-glass':
      return msg('Wine glass');
    case 'character':
      return msg('Character');
  }
}

/** "Sphere", or a model's name for a mesh ("Wine glass"). */
export function shapeName(object: SceneObject): string {
  if (object.shape !== 'mesh') return shapeKindName(object.shape);
  return isModel(object.mesh) ? modelName(object.mesh) : msg('Model');
}

function isModel(name: string | undefined): name is MeshAssetName {
  return (MESH_ASSET_NAMES as readonly (string | undefined)[]).includes(name);
}

export function lightTypeName(type: LightType): string {
  switch (type) {
    case 'point':
      return msg('Point light');
    case 'spot':
      return msg('Spot light');
    case 'area':
      return msg('Area light');
  }
}

/** "Point", where the context already says it is a light. */
export function lightTypeShortName(type: LightType): string {
  switch (type) {
    case 'point':
      return msg('Point');
    case 'spot':
      return msg('Spot');
    case 'area':
      return msg('Area');
  }
}
