import { Vector3 } from 'three';
import type { Color } from '../scene/scene.ts';
import type { TracerLight } from './lights.ts';
import type { RayNode, RayType } from './ray-tree.ts';
import { LightTermsRecorder, type ShadingTerms } from './shading-terms.ts';

/** Missed rays are drawn this long in the ray tree (spec §3). */
export const MISS_LENGTH = 10;

/** Area lights with at least this many samples get one merged node when all agree (spec §3). */
const MERGE_AREA_SAMPLES = 25;

const toCentre = new Vector3();

/** A pixel's ray tree while it is traced (spec §3): its roots, and what each child adds to its parent. */
export class RayTreeRecording {
  /** One root per supersample. */
  readonly roots: RayNode[] = [];
  /** What each child adds to its parent per unit of its colour (ks, kr, kt, a lens ray's 1/(n²·k), or 1). */
  readonly weights = new Map<RayNode, number>();
  /** A hit's colour summed over its channels before clamping: what its children's shares divide (ray-contributions.ts). */
  readonly unclampedSums = new Map<RayNode, number>();

  /** @param withTerms whether hits also get their shading terms (ray-debugger spec §1); the colours are the same either way */
  constructor(readonly withTerms = false) {}
}

/**
 * Records one ray of a pixel's tree while the integrator traces it: the ray's node, its hit's
 * shading terms, its light and shadow rays and its reflected or refracted children (each
 * recorded by a recorder of its own). Rendering passes null for it, so the arithmetic is the
 * same with or without one and a pixel's tree has exactly the image's colour.
 */
export class RayRecorder {
  private terms: ShadingTerms | null = null;
  /** The light being shaded: its terms (with terms) and its sample rays, added at finishLight. */
  private lightTerms: LightTermsRecorder | null = null;
  private lightRays: RayNode[] = [];

  constructor(
    readonly node: RayNode,
    readonly tree: RayTreeRecording = new RayTreeRecording(),
  ) {}

  /** The ray hit nothing: it carries the background. */
  miss(color: Vector3): void {
    end(this.node, false, MISS_LENGTH, null, color);
  }

  /** The hit's ambient term ka·C, first of its terms. */
  ambient(color: Vector3): void {
    if (this.tree.withTerms) this.terms = { ambient: color.toArray(), lights: [], reflect: null, refract: null, sum: [0, 0, 0], depthLimited: false };
  }

  /** Starts a light's share: its ambient term la·Lc·C, then its samples. */
  startLight(light: TracerLight, ambient: Color): void {
    this.lightTerms = this.terms ? new LightTermsRecorder(light.id, ambient) : null;
    this.lightRays = [];
  }

  /** A sample that cast no shadow ray (the light behind the surface, outside its cone, or at the point). */
  noRay(attenuation: number, nDotL: number, rDotV: number): void {
    this.lightTerms?.sample(attenuation, nDotL, rDotV, 'none');
  }

  /** A sample whose shadow ray was blocked by `blockerId` at `length`: it adds black. */
  blocked(attenuation: number, nDotL: number, rDotV: number, from: Vector3, toLight: Vector3, length: number, blockerId: string, lightId: string): void {
    const ray = newNode('shadow', from, toLight, length, true, blockerId, lightId, [0, 0, 0]);
    if (this.lightTerms !== null) ray.parts = { diffuse: [0, 0, 0], specular: [0, 0, 0] };
    this.lightRays.push(ray);
    this.lightTerms?.sample(attenuation, nDotL, rDotV, 'blocked');
  }

  /**
   * A sample that reached the light, adding `diffuse` + `specular`; `untested`: shadows are
   * off, so no shadow ray was cast and the node only records the direction to the light.
   */
  reached(
    attenuation: number,
    nDotL: number,
    rDotV: number,
    from: Vector3,
    toLight: Vector3,
    distance: number,
    lightId: string,
    diffuse: Color,
    specular: Color,
    untested: boolean,
  ): void {
    const ray = newNode('light', from, toLight, distance, true, null, lightId, [diffuse[0] + specular[0], diffuse[1] + specular[1], diffuse[2] + specular[2]]);
    if (untested) ray.untested = true;
    if (this.lightTerms !== null) ray.parts = { diffuse, specular };
    this.lightRays.push(ray);
    this.lightTerms?.sample(attenuation, nDotL, rDotV, 'reached');
  }

  /** Ends a light's share with the sums the integrator added: its rays join the tree, merged into one cone when there are many and all agree. */
  finishLight(light: TracerLight, point: Vector3, diffuse: Color, specular: Color): void {
    const samples = this.lightRays;
    const type = samples[0]?.type;
    const allAgree = samples.length > 0 && samples.every((s) => s.type === type);
    if (light.type !== 'area' || light.sampleCount < MERGE_AREA_SAMPLES || !allAgree) this.node.children.push(...samples);
    else {
      const direction = toCentre.subVectors(light.position, point);
      const distance = direction.length();
      const color = sumOf(samples.map((s) => s.color));
      const merged = newNode(
        type === 'light' ? 'area-light' : 'area-shadow',
        point,
        direction.divideScalar(distance || 1),
        distance,
        true,
        null,
        light.id,
        color,
      );
      merged.corners = light.corners().map((c) => c.toArray()) as RayNode['corners'];
      if (this.tree.withTerms) merged.parts = { diffuse: sumOf(samples.map((s) => s.parts!.diffuse)), specular: sumOf(samples.map((s) => s.parts!.specular)) };
      if (samples[0].untested) merged.untested = true;
      this.node.children.push(merged);
    }
    if (this.terms && this.lightTerms) this.terms.lights.push(this.lightTerms.finish(diffuse, specular));
  }

  /** The hit is at the recursion depth: `wouldContinue` when its material would have reflected or refracted. */
  depthLimited(wouldContinue: boolean): void {
    if (this.terms) this.terms.depthLimited = wouldContinue;
  }

  /** A reflected or refracted ray, adding weight × its colour: its recorder. */
  child(type: 'reflect' | 'refract', origin: Vector3, direction: Vector3, weight: number): RayRecorder {
    const child = newNode(type, origin, direction, 0, false, null, null, [0, 0, 0]);
    this.node.children.push(child);
    this.tree.weights.set(child, weight);
    return new RayRecorder(child, this.tree);
  }

  /** A glossy direction on the wrong side of the surface: not traced, it adds black (an absorbed ray of length 0). */
  absorbed(type: 'reflect' | 'refract', point: Vector3, direction: Vector3, objectId: string | null, weight: number): void {
    const absorbed = newNode(type, point, direction, 0, true, objectId, null, [0, 0, 0]);
    absorbed.glossy = true;
    absorbed.absorbed = true;
    this.node.children.push(absorbed);
    this.tree.weights.set(absorbed, weight);
  }

  /**
   * What a reflected or refracted child added. A rough surface's m² spread rays add up to
   * one term: their weights summed, their colour the weighted mean (weight × colour is then
   * what they add together, up to rounding).
   */
  childTerm(type: 'reflect' | 'refract', weight: number, color: Vector3): void {
    const terms = this.terms;
    if (!terms) return;
    const before = terms[type];
    if (!before) {
      terms[type] = { weight, color: color.toArray() };
      return;
    }
    const total = before.weight + weight;
    terms[type] = { weight: total, color: [0, 1, 2].map((i) => (before.color[i] * before.weight + color.getComponent(i) * weight) / total) as Color };
  }

  /**
   * The ray hit a surface at `length`: `sum` is its colour before clamping (what its terms
   * add up to), `color` after; `normal` is N as the shading turned it toward the ray.
   */
  hit(length: number, objectId: string, normal: Vector3, sum: Color, color: Vector3): void {
    end(this.node, true, length, objectId, color);
    this.tree.unclampedSums.set(this.node, sum[0] + sum[1] + sum[2]);
    this.node.normal = normal.toArray();
    if (this.terms) {
      this.terms.sum = sum;
      this.node.terms = this.terms;
    }
  }
}

function newNode(
  type: RayType,
  origin: Vector3,
  direction: Vector3,
  length: number,
  hit: boolean,
  objectId: string | null,
  lightId: string | null,
  color: Color,
): RayNode {
  return { type, origin: origin.toArray(), direction: direction.toArray(), length, hit, objectId, lightId, color, contribution: 0, children: [] };
}

function end(node: RayNode, hit: boolean, length: number, objectId: string | null, color: Vector3): void {
  node.hit = hit;
  node.length = length;
  node.objectId = objectId;
  node.color = color.toArray();
}

/** Colours added channel by channel, in order, from 0 (as the sample loop adds them). */
function sumOf(colors: readonly (readonly number[])[]): Color {
  return colors.reduce<Color>((sum, c) => [sum[0] + c[0], sum[1] + c[1], sum[2] + c[2]], [0, 0, 0]);
}
