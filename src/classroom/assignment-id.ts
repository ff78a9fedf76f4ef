import { PROGRESS_KEY } from '../quest/progress-store.ts';
import type { Assignment } from './assignment.ts';

/**
 * A short, stable id for an assignment: the same link always gives the same id, so a
 * student who opens it again continues their own progress, and the exports of one class
 * share it. It is a hash, not a secret: nothing is hidden by it.
 */
export function assignmentId(assignment: Assignment): string {
  return fnv1a(JSON.stringify(assignment)).toString(16).padStart(8, '0');
}

/** Where an assignment's progress is kept, apart from free play's (spec/classroom.md). */
export function assignmentProgressKey(assignment: Assignment): string {
  return `${PROGRESS_KEY}.assignment.${assignmentId(assignment)}`;
}

/** FNV-1a, 32 bits: tiny and well spread for short texts; collisions only matter between one teacher's assignments. */
export function fnv1a(text: string, seed = 0x811c9dc5): number {
  let hash = seed;
  for (let i = 0; i < text.length; i++) {
    hash ^= text.charCodeAt(i);
    hash = Math.imul(hash, 0x01000193);
  }
  return hash >>> 0;
}
