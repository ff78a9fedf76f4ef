import { DoubleSide, type Group, Mesh, MeshBasicMaterial, Quaternion, SphereGeometry, Vector3 } from 'three';
import { lobeRadius, type SamplingLobe } from './sampling-lobe.ts';

/** The lobe's colour: a violet no ray is drawn in (ray-palette.ts), so it reads as "not a ray". */
const LOBE_COLOR = 0xa070ff;

/** Segments around the normal and rings from it to the horizon: round enough at a metre, cheap. */
const AROUND = 32;
const RINGS = 12;

const UP = new Vector3(0, 1, 0);

/**
 * Draws a SamplingLobe (sampling-lobe.ts) as a translucent surface with its wire over it, so
 * the rays inside stay visible and its shape reads from any side. One geometry per strategy,
 * made once; a change of vertex only moves and turns it.
 */
export class SamplingLobeMesh {
  private readonly surfaceMaterial = new MeshBasicMaterial({ color: LOBE_COLOR, transparent: true, opacity: 0.16, side: DoubleSide, depthWrite: false });
  private readonly wireMaterial = new MeshBasicMaterial({ color: LOBE_COLOR, transparent: true, opacity: 0.55, wireframe: true, depthWrite: false });
  private readonly geometries = new Map<string, SphereGeometry>();
  private readonly surface = new Mesh(undefined, this.surfaceMaterial);
  private readonly wire = new Mesh(undefined, this.wireMaterial);

  constructor(parent: Group) {
    for (const mesh of [this.surface, this.wire]) {
      mesh.name = 'sampling-lobe';
      mesh.visible = false;
      // Drawn over the rays' start, never picked in place of them or of the objects.
      mesh.raycast = () => {};
      parent.add(mesh);
    }
  }

  show(lobe: SamplingLobe | null): void {
    this.surface.visible = this.wire.visible = lobe !== null;
    if (!lobe) return;
    const geometry = this.geometryFor(lobe);
    const turn = new Quaternion().setFromUnitVectors(UP, new Vector3(...lobe.normal).normalize());
    for (const mesh of [this.surface, this.wire]) {
      mesh.geometry = geometry;
      mesh.position.set(...lobe.point);
      mesh.quaternion.copy(turn);
    }
  }

  dispose(): void {
    for (const geometry of this.geometries.values()) geometry.dispose();
    this.surfaceMaterial.dispose();
    this.wireMaterial.dispose();
  }

  /** The upper hemisphere of a unit sphere (+y the normal), each point pulled to the lobe's radius in its direction. */
  private geometryFor(lobe: SamplingLobe): SphereGeometry {
    const key = `${lobe.sampling} ${lobe.size}`;
    let geometry = this.geometries.get(key);
    if (!geometry) {
      geometry = new SphereGeometry(1, AROUND, RINGS, 0, 2 * Math.PI, 0, Math.PI / 2);
      const position = geometry.getAttribute('position');
      for (let i = 0; i < position.count; i++) {
        const radius = lobeRadius(lobe, position.getY(i));
        position.setXYZ(i, position.getX(i) * radius, position.getY(i) * radius, position.getZ(i) * radius);
      }
      geometry.computeBoundingSphere();
      this.geometries.set(key, geometry);
    }
    return geometry;
  }
}
