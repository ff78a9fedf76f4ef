import { LINK_PREFIX } from './assignment-link.ts';

/**
 * The teacher page opened on an assignment: `#/teacher/a/1.<data>`, the students' link with
 * `teacher/` in front of its `a/`. The page's form is filled from it, so a teacher reopens
 * an assignment from its link in any browser (where nothing of it was kept).
 */
export const TEACHER_LINK_PREFIX = '#/teacher/a/';

/** The teacher page's address for the assignment whose students' fragment is `assignmentHash` (`#/a/1.…`). */
export function teacherLinkHash(assignmentHash: string): string {
  return `#/teacher/${assignmentHash.slice(2)}`;
}

/** The students' fragment (`#/a/1.…`) that a teacher page address carries, or null when it carries none. */
export function assignmentHashOfTeacherLink(hash: string): string | null {
  return hash.startsWith(TEACHER_LINK_PREFIX) ? LINK_PREFIX + hash.slice(TEACHER_LINK_PREFIX.length) : null;
}
