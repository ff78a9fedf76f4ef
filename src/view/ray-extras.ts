import { BufferGeometry, ConeGeometry, CylinderGeometry, type Group, InstancedMesh, type Material } from 'three';
import { ALPHA_ATTRIBUTE, ARROW_AT_ATTRIBUTE, DASH_ATTRIBUTE, GROWTH_ATTRIBUTE, STOP_ATTRIBUTE } from './ray-shader.ts';

/** Sides of an arrowhead: at 10 px wide, 8 already look round. */
const ARROW_SEGMENTS = 8;
/** Sides of a stop plate (14 px across): round enough seen along its ray. */
const STOP_SEGMENTS = 12;

/** Names of the two meshes (for tests and debugging tools). */
export const RAY_ARROWS_NAME = 'ray-arrows';
export const RAY_HIDDEN_NAME = 'ray-hidden-parts';
export const RAY_STOPS_NAME = 'ray-stops';

/**
 * What makes one pixel's rays easy to follow (issue 9: a visible direction, the chosen
 * pixel's rays in front): an arrowhead on each ray, and the parts of the rays that objects
 * hide drawn faintly through them, so a shadow ray behind the ball is still seen, and a
 * plate across the end of each blocked shadow ray where it is stopped. All
 * share the ray cylinders' instance buffers (no copy), and are drawn only for a chosen
 * pixel or the ray debugger's: on a whole screen of rays they would be clutter.
 */
export class RayExtras {
  private readonly arrowGeometry = arrowGeometry();
  private readonly stopGeometry = stopGeometry();
  private readonly arrows: InstancedMesh;
  private readonly hidden: InstancedMesh;
  private readonly stops: InstancedMesh;
  private linkedTo: InstancedMesh | null = null;

  constructor(parent: Group, materials: { arrow: Material; hidden: Material; stop: Material }) {
    this.arrows = extraMesh(this.arrowGeometry, materials.arrow, RAY_ARROWS_NAME);
    this.hidden = extraMesh(new BufferGeometry(), materials.hidden, RAY_HIDDEN_NAME);
    this.stops = extraMesh(this.stopGeometry, materials.stop, RAY_STOPS_NAME);
    // After the rays themselves: the hidden parts test against the depth the rays wrote.
    this.hidden.renderOrder = 1;
    this.arrows.renderOrder = 2;
    this.stops.renderOrder = 2;
    parent.add(this.arrows, this.hidden, this.stops);
  }

  /** How many arrowheads are drawn now. */
  get count(): number {
    return this.arrows.visible ? this.arrows.count : 0;
  }

  /**
   * Draws the extras for the first `count` instances of `cylinders` (the pool's ray mesh), or
   * none when `shown` is false; the stop plates only when `stopped` (some of them are stopped
   * rays), so that a pixel without one costs no draw call for them.
   */
  update(cylinders: InstancedMesh, count: number, shown: boolean, stopped: boolean): void {
    if (this.linkedTo !== cylinders) this.link(cylinders);
    for (const mesh of [this.arrows, this.hidden, this.stops]) {
      const drawn = shown && (mesh !== this.stops || stopped);
      mesh.count = drawn ? count : 0;
      mesh.visible = drawn && count > 0;
    }
  }

  dispose(): void {
    this.arrowGeometry.dispose();
    this.stopGeometry.dispose();
    this.arrows.dispose();
    this.hidden.dispose();
    this.stops.dispose();
  }

  /** Shares the (possibly new, larger) ray mesh's instance buffers. */
  private link(cylinders: InstancedMesh): void {
    for (const geometry of [this.arrowGeometry, this.stopGeometry]) {
      for (const name of [ALPHA_ATTRIBUTE, GROWTH_ATTRIBUTE, DASH_ATTRIBUTE, ARROW_AT_ATTRIBUTE, STOP_ATTRIBUTE]) {
        const attribute = cylinders.geometry.getAttribute(name);
        if (attribute) geometry.setAttribute(name, attribute);
      }
    }
    // The empty geometry the mesh was made with (the rays' own is not ours to dispose).
    if (this.linkedTo === null) this.hidden.geometry.dispose();
    this.hidden.geometry = cylinders.geometry;
    for (const mesh of [this.arrows, this.hidden, this.stops]) {
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

/** A stop plate: a disc of radius 1 across +z, 1 thick, centred on the origin. */
function stopGeometry(): BufferGeometry {
  return new CylinderGeometry(1, 1, 1, STOP_SEGMENTS).rotateX(Math.PI / 2);
}

function extraMesh(geometry: BufferGeometry, material: Material, name: string): InstancedMesh {
  const mesh = new InstancedMesh(geometry, material, 0);
  mesh.name = name;
  mesh.visible = false;
  mesh.frustumCulled = false;
  mesh.raycast = () => {};
  return mesh;
}
