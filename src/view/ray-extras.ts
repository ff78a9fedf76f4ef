import { BufferGeometry, ConeGeometry, type Group, InstancedMesh, type Material } from 'three';
import { ALPHA_ATTRIBUTE, ARROW_AT_ATTRIBUTE, DASH_ATTRIBUTE, GROWTH_ATTRIBUTE } from './ray-shader.ts';

/** Sides of an arrowhead: at 10 px wide, 8 already look round. */
const ARROW_SEGMENTS = 8;

/** Names of the two meshes (for tests and debugging tools). */
export const RAY_ARROWS_NAME = 'ray-arrows';
export const RAY_HIDDEN_NAME = 'ray-hidden-parts';

/**
 * What makes one pixel's rays easy to follow (issue 9: a visible direction, the chosen
 * pixel's rays in front): an arrowhead on each ray, and the parts of the rays that objects
 * hide drawn faintly through them, so a shadow ray behind the ball is still seen. Both
 * share the ray cylinders' instance buffers (no copy), and are drawn only for a chosen
 * pixel or the ray debugger's: on a whole screen of rays they would be clutter.
 */
export class RayExtras {
  private readonly arrowGeometry = arrowGeometry();
  private readonly arrows: InstancedMesh;
  private readonly hidden: InstancedMesh;
  private linkedTo: InstancedMesh | null = null;

  constructor(parent: Group, arrowMaterial: Material, hiddenMaterial: Material) {
    this.arrows = extraMesh(this.arrowGeometry, arrowMaterial, RAY_ARROWS_NAME);
    this.hidden = extraMesh(new BufferGeometry(), hiddenMaterial, RAY_HIDDEN_NAME);
    // After the rays themselves: the hidden parts test against the depth the rays wrote.
    this.hidden.renderOrder = 1;
    this.arrows.renderOrder = 2;
    parent.add(this.arrows, this.hidden);
  }

  /** How many arrowheads are drawn now. */
  get count(): number {
    return this.arrows.visible ? this.arrows.count : 0;
  }

  /** Draws the extras for the first `count` instances of `cylinders` (the pool's ray mesh), or none when `shown` is false. */
  update(cylinders: InstancedMesh, count: number, shown: boolean): void {
    if (this.linkedTo !== cylinders) this.link(cylinders);
    for (const mesh of [this.arrows, this.hidden]) {
      mesh.count = shown ? count : 0;
      mesh.visible = shown && count > 0;
    }
  }

  dispose(): void {
    this.arrowGeometry.dispose();
    this.arrows.dispose();
    this.hidden.dispose();
  }

  /** Shares the (possibly new, larger) ray mesh's instance buffers. */
  private link(cylinders: InstancedMesh): void {
    for (const name of [ALPHA_ATTRIBUTE, GROWTH_ATTRIBUTE, DASH_ATTRIBUTE, ARROW_AT_ATTRIBUTE]) {
      const attribute = cylinders.geometry.getAttribute(name);
      if (attribute) this.arrowGeometry.setAttribute(name, attribute);
    }
    // The empty geometry the mesh was made with (the rays' own is not ours to dispose).
    if (this.linkedTo === null) this.hidden.geometry.dispose();
    this.hidden.geometry = cylinders.geometry;
    for (const mesh of [this.arrows, this.hidden]) {
      mesh.instanceMatrix = cylinders.instanceMatrix;
      mesh.instanceColor = cylinders.instanceColor;
    }
    this.linkedTo = cylinders;
  }
}

/** An arrowhead: tip at the origin pointing +z, base (radius 1) at z = −1. */
function arrowGeometry(): BufferGeometry {
  return new ConeGeometry(1, 1, ARROW_SEGMENTS).rotateX(Math.PI / 2).translate(0, 0, -0.5);
}

function extraMesh(geometry: BufferGeometry, material: Material, name: string): InstancedMesh {
  const mesh = new InstancedMesh(geometry, material, 0);
  mesh.name = name;
  mesh.visible = false;
  mesh.frustumCulled = false;
  mesh.raycast = () => {};
  return mesh;
}
