import { wordedIssue } from '../util/issue.ts';
import type { Assignment } from '../classroom/assignment.ts';
import type { CatalogChapter, CatalogEntry, LevelCatalog } from '../quest/level-index.ts';

/**
 * A teacher's assignment seen by the game: its levels, in its order, make one chapter (so
 * the gate follows the teacher's order); the other levels follow in their own chapters or
 * are left out, as the assignment says. (Its progress key: classroom/assignment-id.ts.)
 */

/** The chapter id of an assignment's levels on the map. */
export const ASSIGNMENT_CHAPTER = 'assignment';

export function assignmentCatalog(catalog: LevelCatalog, assignment: Assignment): LevelCatalog {
  const entries = new Map(catalog.chapters.flatMap((chapter) => chapter.entries.map((entry) => [entry.id, entry] as const)));
  const listed = new Set(assignment.levels);
  const chosen = assignment.levels.map(
    (id): CatalogEntry =>
      entries.get(id) ?? {
        id,
        ok: false,
        errors: [wordedIssue('(root)', `the assignment lists the level "${id}", which this version of the game does not have`)],
      },
  );
  const first: CatalogChapter = { id: ASSIGNMENT_CHAPTER, title: assignment.title, entries: chosen };
  const others =
    assignment.otherLevels === 'shown'
      ? catalog.chapters
          .map((chapter) => ({ ...chapter, entries: chapter.entries.filter((entry) => !listed.has(entry.id)) }))
          .filter((chapter) => chapter.entries.length > 0)
      : [];
  return { chapters: [first, ...others], errors: catalog.errors };
}
