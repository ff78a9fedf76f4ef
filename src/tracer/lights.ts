import { Box3, Vector3 } from 'three';
import type { Light, LightType } from '../scene/scene.ts';
import { interned } from './interned.ts';
import type { RandomStream } from './sampler.ts';
import { RADIANS_PER_DEGREE } from '../util/angles.ts';
import { sceneQuaternion } from './scene-rotation.ts';

/** The types the sample loop compares, kept as this program's own constants (see interned.ts). */
const LIGHT_TYPES: { readonly [K in LightType]: K } = { point: 'point', spot: 'spot', area: 'area' };

/**
 * A light ready for shading: world-space position and axes, cone cosines, and how many
 * samples it takes. Point and spot lights take one sample; an area light n×n jittered ones.
 */
export class TracerLight {
  readonly id: string;
  readonly type: Light['type'];
  readonly position: Vector3;
  /** Lc; intensity and the ambient/diffuse/specular factors stay separate, as in spec §2. */
  readonly color: Vector3;
  readonly intensity: number;
  readonly ambient: number;
  readonly diffuse: number;
  readonly specular: number;
  readonly distanceAttenuation: boolean;
  /** Where the light shines: its local −Y in the world (spot and area). */
  readonly direction = new Vector3(0, -1, 0);
  /** Cosine of half the cone angle: spot spotAngle/2; area 90° (0); point −1 (everywhere). */
  readonly cosHalfAngle: number;
  readonly angleExponent: number;
  /** n: samples per side (1 for point and spot lights). */
  readonly samplesPerSide: number;
  /**
   * 2/n: a grid cell's side in the rectangle's −1..1 coordinates. Multiplying by it gives
   * the same numbers to the bit as dividing by n and doubling when n is a power of two (the
   * benchmark's 4 × 4), within one unit in the last place otherwise; it saves a division per
   * coordinate in the tracer's hottest loop.
   */
  private readonly cellSide: number;
  /** Area lights: the half-extent axes of the rectangle (or disc radii) in the world. */
  readonly halfWidth = new Vector3();
  readonly halfDepth = new Vector3();
  readonly isDisc: boolean;
  /** The box holding every point the light's samples can come from. */
  readonly extent = new Box3();

  constructor(light: Light) {
    this.id = light.id;
    this.type = interned(light.type, LIGHT_TYPES);
    this.position = new Vector3(...light.position);
    this.color = new Vector3(...light.color);
    this.intensity = light.intensity;
    this.ambient = light.ambient;
    this.diffuse = light.diffuse;
    this.specular = light.specular;
    this.distanceAttenuation = light.distanceAttenuation;
    this.cosHalfAngle = -1;
    this.angleExponent = 0;
    this.samplesPerSide = 1;
    this.cellSide = 2;
    this.isDisc = false;
    this.extent.setFromPoints([this.position]);
    if (light.type === 'point') return;
    const rotation = sceneQuaternion(light.rotation);
    this.direction.applyQuaternion(rotation);
    this.angleExponent = light.angleAttenuation;
    if (light.type === 'spot') {
      this.cosHalfAngle = Math.cos((light.spotAngle / 2) * RADIANS_PER_DEGREE);
      return;
    }
    this.cosHalfAngle = 0;
    this.samplesPerSide = light.samples;
    this.cellSide = 2 / light.samples;
    this.isDisc = light.shape === 'disc';
    this.halfWidth.set(light.size[0] / 2, 0, 0).applyQuaternion(rotation);
    this.halfDepth.set(0, 0, light.size[1] / 2).applyQuaternion(rotation);
    for (const corner of this.corners()) this.extent.expandByPoint(corner);
  }

  get sampleCount(): number {
    return this.samplesPerSide * this.samplesPerSide;
  }

  /** The four corners of an area light (the base of the cone drawn for merged area rays). */
  corners(): Vector3[] {
    return [
      [-1, -1],
      [1, -1],
      [1, 1],
      [-1, 1],
    ].map(([u, v]) => this.position.clone().addScaledVector(this.halfWidth, u).addScaledVector(this.halfDepth, v));
  }

  /**
   * The point on the light for sample (i, j), column i and row j of the n×n grid: the
   * light's position for point and spot lights; for an area light, a uniform random point in
   * cell (i, j) (jittered sampling), mapped onto the disc concentrically for disc lights.
   * Written on plain numbers (it runs once per shadow ray), in the order of the Vector3
   * methods it stands for: position + halfWidth·u, then + halfDepth·v.
   */
  samplePoint(i: number, j: number, random: RandomStream, out: Vector3): Vector3 {
    const p = this.position;
    if (this.type !== 'area') return out.copy(p);
    const cell = this.cellSide;
    let u = (i + random.next()) * cell - 1;
    let v = (j + random.next()) * cell - 1;
    // Compared with true, as the flags of the shading loop this is inlined into are
    // (docs/performance.md, "Boolean tests").
    if (this.isDisc === true) {
      // Read by index, not destructured: docs/performance.md, "Array reads".
      const disc = concentricDisc(u, v);
      u = disc[0];
      v = disc[1];
    }
    const w = this.halfWidth;
    const d = this.halfDepth;
    out.x = p.x + w.x * u + d.x * v;
    out.y = p.y + w.y * u + d.y * v;
    out.z = p.z + w.z * u + d.z * v;
    return out;
  }
}

/**
 * Shirley & Chiu's concentric map ("A Low Distortion Map Between Disk and Square", 1997):
 * the square [−1,1]² onto the unit disc, keeping the grid's cells equal in area, so the
 * jittered cells of a disc light stay stratified.
 */
export function concentricDisc(u: number, v: number): [number, number] {
  if (u === 0 && v === 0) return [0, 0];
  let r: number;
  let theta: number;
  if (Math.abs(u) > Math.abs(v)) {
    r = u;
    theta = (Math.PI / 4) * (v / u);
  } else {
    r = v;
    theta = Math.PI / 2 - (Math.PI / 4) * (u / v);
  }
  return [r * Math.cos(theta), r * Math.sin(theta)];
}
