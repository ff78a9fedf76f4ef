import { wordedIssue, type Issue } from '../util/issue.ts';
import { msg, str } from '@lit/localize';
import { describeIssue, issuesOf } from '../scene/scene-issues.ts';
import type { LevelCatalog } from '../quest/level-index.ts';
import type { Assignment } from './assignment.ts';
import { assignmentSchema } from './assignment-schema.ts';
import { packJson, type PackedJsonProblem, unpackJson } from '../util/packed-json.ts';

/**
 * An assignment as a link: `#/a/<version>.<payload>`, the payload being the assignment's
 * JSON compressed with zlib deflate and written in base64url. Everything is in the
 * fragment, so no server ever sees it and any static host (or a USB stick) works.
 *
 * zlib's format (not raw deflate) because it ends in a checksum: a link that was cut short
 * or had a character changed fails to open instead of opening as a different assignment.
 * Compression keeps a typical link under 300 characters, small enough for a QR code that
 * reads from the back of a classroom.
 */

/** The link format's version: a later app that changes the payload bumps it and keeps reading 1. */
export const LINK_VERSION = 1;
export const LINK_PREFIX = '#/a/';

/**
 * The most an assignment link may unpack to. The largest assignment the schema accepts
 * (100 levels, each with 100 required tasks of 64-character ids) is about 700 kB; a real
 * one is under 2 kB. A 408 kB link once unpacked to 300 MB.
 */
export const MAX_ASSIGNMENT_BYTES = 1024 * 1024;

/** Why a link did not open: the link itself is damaged, from another version, or names levels or tasks this game does not have. */
export type LinkProblemKind = 'damaged' | 'other-version' | 'unknown-levels';

export type AssignmentLinkResult = { ok: true; assignment: Assignment } | { ok: false; kind: LinkProblemKind; reasons: Issue[] };

/** Whether an address fragment is meant as an assignment link (damaged or not). */
export function isAssignmentFragment(hash: string): boolean {
  return hash.startsWith(LINK_PREFIX);
}

/** The fragment (with its `#`) that opens `assignment`. */
export async function encodeAssignment(assignment: Assignment): Promise<string> {
  return `${LINK_PREFIX}${LINK_VERSION}.${await packJson(assignment)}`;
}

/** The whole address for students: the app's address without its fragment, plus the assignment's. */
export async function assignmentUrl(assignment: Assignment, appAddress: string): Promise<string> {
  return `${appAddress.replace(/#.*$/, '')}${await encodeAssignment(assignment)}`;
}

/**
 * Reads an assignment fragment, checking it all the way: the version, the checksum, the
 * JSON, every field, and (given the catalog) that its levels and tasks exist.
 */
export async function decodeAssignment(hash: string, catalog?: LevelCatalog): Promise<AssignmentLinkResult> {
  if (!isAssignmentFragment(hash)) return damaged(msg('it does not start with #/a/'));
  const body = hash.slice(LINK_PREFIX.length);
  const dot = body.indexOf('.');
  if (dot < 0) return damaged(msg('the version number is missing'));
  const version = body.slice(0, dot);
  if (version !== String(LINK_VERSION)) {
    const reason = msg(str`the link has version ${JSON.stringify(version)}; this app opens version ${LINK_VERSION}`);
    return { ok: false, kind: 'other-version', reasons: [wordedIssue(null, reason)] };
  }
  const unpacked = await unpackJson(body.slice(dot + 1), MAX_ASSIGNMENT_BYTES);
  if (!unpacked.ok) return damaged(packedProblemText(unpacked));
  const parsed = assignmentSchema.safeParse(unpacked.value, { error: describeIssue });
  if (!parsed.success) return { ok: false, kind: 'damaged', reasons: issuesOf(parsed.error.issues) };
  const unknown = catalog ? unknownParts(parsed.data, catalog) : [];
  if (unknown.length === 0) return { ok: true, assignment: parsed.data };
  return { ok: false, kind: 'unknown-levels', reasons: unknown.map((part) => wordedIssue(null, part)) };
}

/** The levels and required tasks of `assignment` that the catalog does not have, as "level" or "level/task". */
export function unknownParts(assignment: Assignment, catalog: LevelCatalog): string[] {
  const entries = new Map(catalog.chapters.flatMap((chapter) => chapter.entries.map((entry) => [entry.id, entry] as const)));
  const unknown: string[] = assignment.levels.filter((id) => !entries.has(id));
  for (const [levelId, tasks] of Object.entries(assignment.requiredTasks)) {
    const entry = entries.get(levelId);
    // A broken level's tasks cannot be checked: the game shows it as broken anyway.
    if (!entry?.ok) continue;
    for (const task of tasks) if (!entry.level.tasks.some((known) => known.id === task)) unknown.push(`${levelId}/${task}`);
  }
  return unknown;
}

/** Why the link's payload did not unpack (said in the learner's language). */
function packedProblemText(unpacked: PackedJsonProblem): Issue | string {
  switch (unpacked.problem) {
    case 'not-base64url':
      return msg('it contains characters that cannot be part of a link, or it was cut short');
    case 'damaged':
      return msg('it was cut short or changed');
    case 'too-large':
      return msg(str`it unpacks to more than ${unpacked.limit / 1024} kB, more than any assignment`);
    case 'not-json':
      return unpacked.issue;
  }
}

function damaged(reason: Issue | string): AssignmentLinkResult {
  return { ok: false, kind: 'damaged', reasons: [typeof reason === 'string' ? wordedIssue(null, reason) : reason] };
}
