import { BoxGeometry, BufferAttribute, BufferGeometry, CylinderGeometry, PlaneGeometry, SphereGeometry } from 'three';
import type { MeshLibrary } from '../../src/scene/mesh-data.ts';
import type { SceneObject } from '../../src/scene/scene.ts';

/** The unit shapes of spec §1 as triangles (object space), at the tessellation a tutorial would pick. */
export function tessellate(object: SceneObject, meshes: MeshLibrary): BufferGeometry {
  switch (object.shape) {
    case 'sphere':
      return new SphereGeometry(0.5, 48, 24);
    case 'box':
      return new BoxGeometry(1, 1, 1);
    case 'cylinder':
      return new CylinderGeometry(0.5, 0.5, 1, 48);
    case 'plane':
      return new PlaneGeometry(1, 1).rotateX(-Math.PI / 2);
    case 'mesh': {
      const data = meshes.get(object.mesh!)!;
      const geometry = new BufferGeometry();
      geometry.setAttribute('position', new BufferAttribute(data.positions.slice(), 3));
      geometry.setIndex(new BufferAttribute(data.indices.slice(), 1));
      return geometry;
    }
  }
}
