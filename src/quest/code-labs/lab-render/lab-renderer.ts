import { Vector3 } from 'three';
import type { Material } from '../../../scene/scene.ts';
import { schlickReflectance } from '../../../tracer/fresnel.ts';
import { Hit } from '../../../tracer/hit.ts';
import { Ray } from '../../../tracer/ray.ts';
import type { Rgb, Vec3 } from '../code-lab-grading.ts';
import type { Point } from '../code-lab-statistics.ts';
import { dot, scaled, v } from '../lab-vectors.ts';
import type { PhongMaterial } from '../phong-lab.ts';
import type { Sphere } from '../shadow-lab.ts';
import { levelCamera, type LabCamera } from './lab-camera.ts';
import type { LabFunctions } from './lab-functions.ts';
import type { LabBox, LabRenderScene } from './lab-render-scene.ts';

/** The nearest hit of a ray: where, the outward unit normal there, and the material. */
interface LabHit {
  point: Vec3;
  normal: Vec3;
  material: Material;
}

const along = (origin: Vec3, direction: Vec3, t: number): Vec3 => v(origin.x + t * direction.x, origin.y + t * direction.y, origin.z + t * direction.z);
const clamp = (c: number) => Math.min(1, Math.max(0, c));
const fromVector = (vector: Vector3): Vec3 => v(vector.x, vector.y, vector.z);

/**
 * Renders a scene the way the code labs describe the tracer, every step one of the labs'
 * functions (`functions`): Whitted's model (Whitted 1980; Shirley & Marschner, "Fundamentals
 * of Computer Graphics", 4th ed., ch. 4 and §13.1) with the Phong lab's shade per light
 * (each light a point light, A = 1), the shadow lab's test per light, the mirror lab's
 * direction for every mirror hit and for glass's reflected ray, and the refraction lab's
 * direction (null: total internal reflection, all reflected) with Schlick's kr for glass.
 * Spheres are met by the ray–sphere lab's test, boxes along the axes by the box lab's slab
 * test (Kay & Kajiya 1986), the other shapes by the tracer's own. One ray through each of
 * the pixel's points (`pixelPoints`, offsets in [0, 1)² from its top-left corner; by default
 * its centre), from the level's camera unless another is given, each ray's colour clamped to
 * 0..1 and the pixel their average, as the tracer's supersampling does. Returns linear RGB,
 * row by row from the top, as the tracer's images.
 */
export async function renderLab(
  scene: LabRenderScene,
  functions: LabFunctions,
  width: number,
  height: number,
  { camera = levelCamera(scene), pixelPoints = () => PIXEL_CENTRE }: LabRenderView = {},
): Promise<Float32Array> {
  const tracer = new LabTracer(scene, functions);
  const image = new Float32Array(width * height * 3);
  for (let y = 0; y < height; y++) {
    // A render runs on the page's thread (the learner's answers are already in a table), a
    // pass up to a second on a slow laptop: between bands of rows the page handles its input.
    if (y > 0 && y % ROWS_PER_TURN === 0) await nextTurn();
    for (let x = 0; x < width; x++) {
      const points = pixelPoints(x, y);
      const sum = { r: 0, g: 0, b: 0 };
      for (const point of points) {
        const { origin, direction } = camera(x + point.x, y + point.y, width, height);
        const color = tracer.trace(origin, direction, 0);
        sum.r += color.r;
        sum.g += color.g;
        sum.b += color.b;
      }
      image.set([sum.r / points.length, sum.g / points.length, sum.b / points.length], (y * width + x) * 3);
    }
  }
  return image;
}

/** How a lab render looks at its scene: the camera (the level's by default) and the points of each pixel its rays go through (its centre by default). */
export interface LabRenderView {
  camera?: LabCamera;
  pixelPoints?: (x: number, y: number) => readonly Point[];
}

const PIXEL_CENTRE: readonly Point[] = [{ x: 0.5, y: 0.5 }];

/**
 * The outward normal of the box's face a point lies on: along the axis where the point is
 * farthest out relative to the box's half-size (on a face that ratio is 1), toward its side.
 */
function faceNormal({ min, max }: LabBox, point: Vec3): Vec3 {
  let axis: 'x' | 'y' | 'z' = 'x';
  let outmost = -1;
  let side = 1;
  for (const a of ['x', 'y', 'z'] as const) {
    const half = (max[a] - min[a]) / 2;
    const offset = (point[a] - (min[a] + max[a]) / 2) / half;
    if (Math.abs(offset) > outmost) {
      outmost = Math.abs(offset);
      axis = a;
      side = Math.sign(offset) || 1;
    }
  }
  return v(axis === 'x' ? side : 0, axis === 'y' ? side : 0, axis === 'z' ? side : 0);
}

/** Rows rendered before the page gets a turn: at 160 pixels a row, a band of a few milliseconds. */
export const ROWS_PER_TURN = 8;

/** A macrotask's turn, so that input events and frames run between bands (a resolved promise would not let them). */
export const nextTurn = () => new Promise<void>((resolve) => setTimeout(resolve, 0));

class LabTracer {
  private readonly ray = new Ray();
  private readonly hit = new Hit();
  private readonly vector = new Vector3();
  /** The spheres as the shadow lab's function takes them: a centre and a radius. */
  private readonly blockers: Sphere[];

  constructor(
    private readonly scene: LabRenderScene,
    private readonly functions: LabFunctions,
  ) {
    this.blockers = scene.spheres.map(({ center, radius }) => ({ center, radius }));
  }

  trace(origin: Vec3, direction: Vec3, depth: number): Rgb {
    const hit = this.nearest(origin, direction);
    if (!hit) {
      const [r, g, b] = this.scene.source.settings.background;
      return { r, g, b };
    }
    const color = this.shade(direction, hit, depth);
    return { r: clamp(color.r), g: clamp(color.g), b: clamp(color.b) };
  }

  /** The nearest hit: the tracer's shapes first, then each sphere by the sphere test and each box by the slab test (any t they give nearer counts). */
  private nearest(origin: Vec3, direction: Vec3): LabHit | null {
    const { ray, hit } = this;
    ray.set(this.vector.set(origin.x, origin.y, origin.z), new Vector3(direction.x, direction.y, direction.z));
    hit.reset(Infinity);
    this.scene.others.objects.nearest(ray, hit, null);
    let nearest = hit.t;
    let sphere = null;
    for (const candidate of this.scene.spheres) {
      const t = this.functions.hitSphere(origin, direction, candidate.center, candidate.radius);
      if (t !== null && t < nearest) {
        nearest = t;
        sphere = candidate;
      }
    }
    let box = null;
    for (const candidate of this.scene.boxes) {
      const t = this.functions.hitBox(origin, direction, candidate.min, candidate.max);
      if (t !== null && t < nearest) {
        nearest = t;
        box = candidate;
        sphere = null;
      }
    }
    if (box) {
      const point = along(origin, direction, nearest);
      return { point, normal: faceNormal(box, point), material: box.material };
    }
    if (sphere) {
      const point = along(origin, direction, nearest);
      const { center, radius } = sphere;
      return { point, normal: v((point.x - center.x) / radius, (point.y - center.y) / radius, (point.z - center.z) / radius), material: sphere.material };
    }
    if (!hit.shape) return null;
    hit.shape.surface(ray, hit);
    return { point: fromVector(hit.point), normal: fromVector(hit.normal), material: hit.shape.material };
  }

  /** The local light of every light, then the mirror or glass rays; unclamped. */
  private shade(direction: Vec3, { point, normal, material }: LabHit, depth: number): Rgb {
    // The normal turned toward the incoming ray; a back-face hit means the ray is inside.
    const entering = dot(normal, direction) < 0;
    const facing = entering ? normal : scaled(normal, -1);
    const toEye = scaled(direction, -1);
    const [cr, cg, cb] = material.color;
    const surface: PhongMaterial = { color: { r: cr, g: cg, b: cb }, diffuse: material.diffuse, specular: material.specular, shininess: material.shininess };
    const out = { r: material.ambient * cr, g: material.ambient * cg, b: material.ambient * cb };
    // Shadow rays and reflected rays start ε off the surface on the side they leave by, as the tracer's do (shading-frame.ts).
    const epsilon = this.scene.others.epsilon;
    const outside = along(point, facing, epsilon);
    for (const { ambient, ...light } of this.scene.lights) {
      out.r += ambient * light.color.r * cr;
      out.g += ambient * light.color.g * cg;
      out.b += ambient * light.color.b * cb;
      if (this.lightBlocked(outside, facing, light.position)) continue;
      const lit = this.functions.shade(point, facing, toEye, light, surface);
      out.r += lit.r;
      out.g += lit.g;
      out.b += lit.b;
    }
    if (depth >= this.scene.source.settings.maxDepth) return out;
    if (material.transparent) this.addGlass(direction, normal, facing, point, material.refractiveIndex, entering, depth, out);
    else if (material.specular > 0) this.addChild(outside, this.functions.reflect(direction, facing), material.specular, depth, out);
    return out;
  }

  /**
   * Whether the light is hidden from a point: behind the surface (the shade is 0 there and no
   * shadow ray is cast, as in the tracer), or a shadow ray toward it is blocked by a sphere
   * (the shadow test), by a box (the slab test, met at 0 < t < the distance, the shadow lab's
   * rule) or by one of the other shapes (the tracer's any-hit test).
   */
  private lightBlocked(outside: Vec3, facing: Vec3, lightPosition: Vec3): boolean {
    const toLight = v(lightPosition.x - outside.x, lightPosition.y - outside.y, lightPosition.z - outside.z);
    const distance = Math.hypot(toLight.x, toLight.y, toLight.z);
    if (distance === 0 || dot(toLight, facing) <= 0 || !this.scene.source.settings.shadows) return false;
    const unit = scaled(toLight, 1 / distance);
    if (this.functions.inShadow(outside, unit, distance, this.blockers)) return true;
    if (this.scene.boxes.some(({ min, max }) => (this.functions.hitBox(outside, unit, min, max) ?? Infinity) < distance)) return true;
    const ray = this.ray.set(this.vector.set(outside.x, outside.y, outside.z), new Vector3(unit.x, unit.y, unit.z));
    ray.far = distance;
    return this.scene.others.occluders.some((occluders) => occluders.firstBlocker(ray, null, null) !== null);
  }

  /** Glass: kt·Li(refracted) + kr·Li(reflected) with Schlick's kr; on total internal reflection, all reflected. */
  private addGlass(direction: Vec3, normal: Vec3, facing: Vec3, point: Vec3, ior: number, entering: boolean, depth: number, out: Rgb): void {
    const outside = along(point, facing, this.scene.others.epsilon);
    const reflected = this.functions.reflect(direction, facing);
    const refracted = this.functions.refract(direction, normal, ior);
    if (refracted === null) {
      this.addChild(outside, reflected, 1, depth, out);
      return;
    }
    // Schlick with the angle on the less dense side: θi entering, θt leaving.
    const kr = schlickReflectance(entering ? -dot(direction, facing) : -dot(refracted, facing), ior);
    this.addChild(along(point, facing, -this.scene.others.epsilon), refracted, 1 - kr, depth, out);
    this.addChild(outside, reflected, kr, depth, out);
  }

  private addChild(origin: Vec3, direction: Vec3, weight: number, depth: number, out: Rgb): void {
    const color = this.trace(origin, direction, depth + 1);
    out.r += weight * color.r;
    out.g += weight * color.g;
    out.b += weight * color.b;
  }
}
