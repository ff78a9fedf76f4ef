import { Box3, Vector3, type BufferGeometry } from 'three';

/**
 * Scales a model uniformly to exactly 1 m tall and centres its bounding box on the origin,
 * so that every model spans y from -0.5 to 0.5 like the unit box: a scene places any of
 * them on the floor at `position.y = 0.5 · scale.y`.
 */
export function fitToUnitHeight(geometry: BufferGeometry): BufferGeometry {
  geometry.computeBoundingBox();
  const bounds = geometry.boundingBox ?? new Box3();
  const centre = bounds.getCenter(new Vector3());
  const height = bounds.max.y - bounds.min.y;
  geometry.translate(-centre.x, -centre.y, -centre.z);
  geometry.scale(1 / height, 1 / height, 1 / height);
  return geometry;
}
