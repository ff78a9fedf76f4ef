import type { LabAnswer, Rgb, Vec3 } from '../code-lab-grading.ts';
import type { CodeLab } from '../code-goal.ts';
import { tracerReflect } from '../mirror-lab.ts';
import { tracerPhong, type PhongLight, type PhongMaterial } from '../phong-lab.ts';
import { tracerHitBox } from '../ray-box-lab.ts';
import { tracerHitSphere } from '../ray-sphere-lab.ts';
import { tracerRefract } from '../refraction-lab.ts';
import type { Sphere } from '../shadow-lab.ts';

/**
 * The six functions a lab render is made of, each with the contract of its lab: the sphere
 * test, the box's slab test, the mirror direction, the refraction, the shade for one light,
 * the shadow test.
 */
export interface LabFunctions {
  hitSphere(origin: Vec3, direction: Vec3, center: Vec3, radius: number): number | null;
  hitBox(origin: Vec3, direction: Vec3, boxMin: Vec3, boxMax: Vec3): number | null;
  reflect(d: Vec3, n: Vec3): Vec3;
  refract(d: Vec3, outward: Vec3, ior: number): Vec3 | null;
  shade(point: Vec3, normal: Vec3, toEye: Vec3, light: PhongLight, material: PhongMaterial): Rgb;
  inShadow(point: Vec3, toLight: Vec3, distanceToLight: number, spheres: readonly Sphere[]): boolean;
}

/** The labs whose function a lab render can take in place of the tracer's. */
export const RENDER_LABS = ['ray-sphere', 'ray-box', 'mirror', 'refraction', 'phong', 'shadow'] as const satisfies readonly CodeLab[];
export type RenderLab = (typeof RENDER_LABS)[number];

export const rendersWith = (lab: CodeLab): lab is RenderLab => (RENDER_LABS as readonly CodeLab[]).includes(lab);

/** Which of the five functions a lab's learner writes. */
const SLOT: Record<RenderLab, keyof LabFunctions> = {
  'ray-sphere': 'hitSphere',
  'ray-box': 'hitBox',
  mirror: 'reflect',
  refraction: 'refract',
  phong: 'shade',
  shadow: 'inShadow',
};

/**
 * The functions with the lab's one answered by `answer` (its arguments in the lab's order)
 * and the others by the tracer's own (the labs' reference functions). The shadow test is
 * the tracer's rule built on whichever sphere test is in use (shadow-lab.ts: a sphere blocks
 * when met at 0 < t < the distance), so in the ray–sphere lab every shadow ray uses the
 * learner's sphere test too.
 */
export function labFunctions(lab: RenderLab | null, answer: (args: unknown[]) => LabAnswer): LabFunctions {
  const functions: LabFunctions = {
    hitSphere: tracerHitSphere,
    hitBox: tracerHitBox,
    reflect: tracerReflect,
    refract: tracerRefract,
    shade: tracerPhong,
    inShadow: (point, toLight, distance, spheres) =>
      spheres.some((sphere) => (functions.hitSphere(point, toLight, sphere.center, sphere.radius) ?? Infinity) < distance),
  };
  if (lab !== null) Object.assign(functions, { [SLOT[lab]]: (...args: unknown[]) => answer(args) });
  return functions;
}

/** The tracer's own answer to one call of the lab's function. */
export function referenceAnswer(lab: RenderLab, args: unknown[]): LabAnswer {
  const reference = labFunctions(null, () => null);
  return (reference[SLOT[lab]] as (...args: unknown[]) => LabAnswer)(...args);
}
