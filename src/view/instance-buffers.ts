/**
 * The pooled instance buffers of the drawn rays (ray-pool.ts): one InstancedMesh of ribbons or of
 * pyramids with its per-instance attributes, grown by doubling and never shrunk, uploading only
 * the range in use.
 */
import { BufferGeometry, Float32BufferAttribute, type Group, InstancedBufferAttribute, InstancedMesh, type Material } from 'three';
import { ALPHA_ATTRIBUTE, ARROW_AT_ATTRIBUTE, DASH_ATTRIBUTE, GROWTH_ATTRIBUTE, STOP_ATTRIBUTE } from './ray-shader.ts';

/** Instances allocated at first; the buffers double from there as needed. */
const INITIAL_CAPACITY = 256;

/** Floats per instance: matrix 16, colour 3, alpha 1, growth 2; a cylinder adds its dash 2, arrowhead place 1 and stop 1. */
export const FLOATS_PER_CONE = 22;
export const FLOATS_PER_CYLINDER = FLOATS_PER_CONE + 4;

/** Names of the two meshes in RayPool.object (for tests and debugging tools). */
export const RAY_CYLINDERS_NAME = 'ray-cylinders';
export const RAY_CONES_NAME = 'ray-cones';

/** One instanced mesh and its capacity; replaced by a twice larger one when full. */
export class InstanceBuffers {
  mesh: InstancedMesh;
  private readonly kind: 'cylinder' | 'cone';

  constructor(
    kind: 'cylinder' | 'cone',
    material: Material,
    private readonly parent: Group,
  ) {
    this.kind = kind;
    this.mesh = this.createMesh(INITIAL_CAPACITY, material);
    parent.add(this.mesh);
  }

  get capacity(): number {
    return this.mesh.instanceMatrix.count;
  }

  get alpha(): InstancedBufferAttribute {
    return this.mesh.geometry.getAttribute(ALPHA_ATTRIBUTE) as InstancedBufferAttribute;
  }

  get growth(): InstancedBufferAttribute {
    return this.mesh.geometry.getAttribute(GROWTH_ATTRIBUTE) as InstancedBufferAttribute;
  }

  get color(): InstancedBufferAttribute {
    return this.mesh.instanceColor as InstancedBufferAttribute;
  }

  /** The dash pattern by instance (cylinders only; see RAY_DASHES). */
  get dash(): InstancedBufferAttribute | undefined {
    return this.mesh.geometry.getAttribute(DASH_ATTRIBUTE) as InstancedBufferAttribute | undefined;
  }

  /** Where each instance's arrowhead sits along it (cylinders only; the arrows share it). */
  get arrowAt(): InstancedBufferAttribute | undefined {
    return this.mesh.geometry.getAttribute(ARROW_AT_ATTRIBUTE) as InstancedBufferAttribute | undefined;
  }

  /** 1 where an instance is a stopped ray with a plate at its end (cylinders only; the plates share it). */
  get stop(): InstancedBufferAttribute | undefined {
    return this.mesh.geometry.getAttribute(STOP_ATTRIBUTE) as InstancedBufferAttribute | undefined;
  }

  /** Makes room for `count` instances, replacing the mesh (and freeing its GPU buffers) when too small. */
  reserve(count: number): void {
    if (count <= this.capacity) return;
    let capacity = this.capacity;
    while (capacity < count) capacity *= 2;
    const old = this.mesh;
    this.mesh = this.createMesh(capacity, old.material as Material);
    this.parent.remove(old);
    this.parent.add(this.mesh);
    old.geometry.dispose();
    old.dispose();
  }

  /** The instance attributes (the matrix first), to copy a range of them into a piece. */
  get attributes(): InstancedBufferAttribute[] {
    return [
      this.mesh.instanceMatrix,
      this.color,
      this.alpha,
      this.growth,
      ...(this.dash ? [this.dash] : []),
      ...(this.arrowAt ? [this.arrowAt] : []),
      ...(this.stop ? [this.stop] : []),
    ];
  }

  /** Instances `from` … `to` − 1 of `source` as this mesh's first ones, drawn alone (a piece: RayPool.piece). */
  copyRange(source: InstanceBuffers, from: number, to: number): void {
    const count = Math.max(0, to - from);
    this.reserve(count);
    const targets = this.attributes;
    source.attributes.forEach((attribute, a) => {
      const size = attribute.itemSize;
      (targets[a].array as Float32Array).set((attribute.array as Float32Array).subarray(from * size, to * size));
    });
    this.commit(count);
  }

  /** Draws the first `count` instances only (those uploaded stay), or all `uploaded` of them. */
  limit(count: number, uploaded: number): void {
    this.mesh.count = Math.min(count, uploaded);
    this.mesh.visible = this.mesh.count > 0;
  }

  /** Uploads the first `count` instances and draws that many. */
  commit(count: number): void {
    this.mesh.count = count;
    this.mesh.visible = count > 0;
    if (count === 0) return;
    for (const attribute of this.attributes) {
      attribute.clearUpdateRanges();
      attribute.addUpdateRange(0, count * attribute.itemSize);
      attribute.needsUpdate = true;
    }
  }

  dispose(): void {
    this.mesh.geometry.dispose();
    this.mesh.dispose();
  }

  private createMesh(capacity: number, material: Material): InstancedMesh {
    const geometry = this.kind === 'cone' ? pyramidGeometry() : ribbonGeometry();
    geometry.setAttribute(ALPHA_ATTRIBUTE, new InstancedBufferAttribute(new Float32Array(capacity), 1));
    geometry.setAttribute(GROWTH_ATTRIBUTE, new InstancedBufferAttribute(new Float32Array(capacity * 2), 2));
    if (this.kind === 'cylinder') {
      geometry.setAttribute(DASH_ATTRIBUTE, new InstancedBufferAttribute(new Float32Array(capacity * 2), 2));
      geometry.setAttribute(ARROW_AT_ATTRIBUTE, new InstancedBufferAttribute(new Float32Array(capacity), 1));
      geometry.setAttribute(STOP_ATTRIBUTE, new InstancedBufferAttribute(new Float32Array(capacity), 1));
    }
    const mesh = new InstancedMesh(geometry, material, capacity);
    mesh.name = this.kind === 'cone' ? RAY_CONES_NAME : RAY_CYLINDERS_NAME;
    mesh.instanceColor = new InstancedBufferAttribute(new Float32Array(capacity * 3), 3);
    mesh.count = 0;
    mesh.visible = false;
    // The rays are spread over the whole scene and change every update: a bounding sphere
    // over 50k instance matrices would cost more than it ever culls.
    mesh.frustumCulled = false;
    // Hover goes through RayPool.pick; three's per-instance raycast would test 50k
    // instances whenever the view raycasts its scene to select an object.
    mesh.raycast = () => {};
    return mesh;
  }
}

/**
 * A ray's ribbon: x = ±1 across it, z from 0 to 1 along it. The vertex shader turns it to
 * face the eye at the width of the instance's cylinder (ray-shader.ts): the instances keep
 * a cylinder's matrix (axis and radius), and 2 triangles do what a six-sided cylinder's 12 did.
 */
function ribbonGeometry(): BufferGeometry {
  const positions = [-1, 0, 0, 1, 0, 0, -1, 0, 1, 1, 0, 1];
  return new BufferGeometry().setAttribute('position', new Float32BufferAttribute(positions, 3)).setIndex([0, 1, 2, 2, 1, 3]);
}

/**
 * An area cone: apex at the origin, base corners (∓1, ∓1, 1) in RayNode.corners order, so
 * one affine instance matrix maps it onto any hit point and light rectangle (or glossy fan base).
 */
function pyramidGeometry(): BufferGeometry {
  const base = [
    [-1, -1, 1],
    [1, -1, 1],
    [1, 1, 1],
    [-1, 1, 1],
  ];
  const positions: number[] = [];
  for (let k = 0; k < 4; k++) positions.push(0, 0, 0, ...base[k], ...base[(k + 1) % 4]);
  positions.push(...base[0], ...base[2], ...base[1], ...base[0], ...base[3], ...base[2]);
  return new BufferGeometry().setAttribute('position', new Float32BufferAttribute(positions, 3));
}
