import type { RandomStream } from '../../tracer/sampler.ts';
import type { Vec3 } from './code-lab-grading.ts';

/** The labs' cases are written with plain vectors, the learner's kind (cloneable to the sandbox). */
export const v = (x: number, y: number, z: number): Vec3 => ({ x, y, z });

export const dot = (a: Vec3, b: Vec3): number => a.x * b.x + a.y * b.y + a.z * b.z;

export const scaled = (a: Vec3, s: number): Vec3 => v(a.x * s, a.y * s, a.z * s);

export const unit = (a: Vec3): Vec3 => scaled(a, 1 / Math.hypot(a.x, a.y, a.z));

/** A direction uniform over the sphere of directions (Archimedes: z uniform in [-1, 1]). */
export function randomDirection(random: RandomStream): Vec3 {
  const z = 2 * random.next() - 1;
  const phi = 2 * Math.PI * random.next();
  const r = Math.sqrt(1 - z * z);
  return v(r * Math.cos(phi), r * Math.sin(phi), z);
}
