import { msg } from '@lit/localize';
import type { LightType, SceneObject, ShapeKind } from '../../scene/scene.ts';
import { MESH_ASSET_NAMES, type MeshAssetName } from '../../scene/mesh-assets.ts';

/** The words the panels use for shapes, models and light types (translated, unlike ids), and the scene's own names. */

// The scene's own names live with the language (the 3D view names the selection too).
export { itemName, shownName } from '../../i18n/scene-item-names.ts';

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
