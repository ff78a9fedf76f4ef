import { readFileSync, existsSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import type { Assignment } from '../../src/classroom/assignment.ts';
import { assignmentId, assignmentProgressKey } from '../../src/classroom/assignment-id.ts';
import { assignmentUrl, decodeAssignment, encodeAssignment, isAssignmentFragment } from '../../src/classroom/assignment-link.ts';
import { issueLine } from '../../src/util/issue.ts';
import { fromBase64Url, toBase64Url } from '../../src/util/base64url.ts';
import { deflate } from '../../src/util/zlib-bytes.ts';
import { loadLevels } from '../../src/quest/level-index.ts';
import { PROGRESS_KEY } from '../../src/quest/progress-store.ts';

const levelsFolder = new URL('../../levels/', import.meta.url);

/** A decoded link with its reasons as the English lines `rt validate` prints. */
async function decoded(...args: Parameters<typeof decodeAssignment>) {
  const result = await decodeAssignment(...args);
  return result.ok ? result : { ...result, reasons: result.reasons.map(issueLine) };
}
const readLevelFile = (name: string) => (existsSync(new URL(name, levelsFolder)) ? readFileSync(new URL(name, levelsFolder), 'utf8') : undefined);
const catalog = loadLevels(readFileSync(new URL('index.json', levelsFolder), 'utf8'), readLevelFile);

const lesson: Assignment = {
  version: 1,
  title: 'Ray tracing, lesson 2 — "shadows", ü',
  levels: ['02-rays-from-the-camera', '01-introduction'],
  requiredTasks: { '01-introduction': ['orbit'] },
  otherLevels: 'hidden',
  locale: 'nl',
  askParticipantCode: true,
  survey: 'default',
};

/** The payload with one character changed to another base64url character. */
function flip(fragment: string, at: number): string {
  const index = fragment.length - at;
  const replacement = fragment[index] === 'A' ? 'B' : 'A';
  return fragment.slice(0, index) + replacement + fragment.slice(index + 1);
}

describe('assignment links', () => {
  it('round-trips an assignment, levels and tasks checked against the catalog', async () => {
    const fragment = await encodeAssignment(lesson);
    expect(fragment).toMatch(/^#\/a\/1\.[A-Za-z0-9_-]+$/);
    expect(isAssignmentFragment(fragment)).toBe(true);
    expect(await decoded(fragment, catalog)).toEqual({ ok: true, assignment: lesson });
  });

  it("round-trips the teacher's choice of survey questions, and refuses one that is not yes or no", async () => {
    const chosen: Assignment = { ...lesson, surveyQuestions: { age: false, 'learned-soft-shadows': true } };
    expect(await decoded(await encodeAssignment(chosen), catalog)).toEqual({ ok: true, assignment: chosen });
    const wrong = { ...lesson, surveyQuestions: { age: 'no' } } as unknown as Assignment;
    expect(await decoded(await encodeAssignment(wrong), catalog)).toMatchObject({ ok: false, kind: 'damaged' });
  });

  it('is short enough for a QR code a phone reads from a projector', async () => {
    const url = await assignmentUrl(lesson, 'https://school.example/rt-quest/index.html#/teacher');
    expect(url.startsWith('https://school.example/rt-quest/index.html#/a/1.')).toBe(true);
    expect(url.length).toBeLessThan(400);
  });

  it('refuses a link that was cut short', async () => {
    const fragment = await encodeAssignment(lesson);
    const result = await decoded(fragment.slice(0, -6));
    expect(result).toMatchObject({ ok: false, kind: 'damaged' });
  });

  it('refuses a link with a changed character (the checksum catches it)', async () => {
    const fragment = await encodeAssignment(lesson);
    for (const at of [1, 5, 20, 60]) expect(await decoded(flip(fragment, at))).toMatchObject({ ok: false, kind: 'damaged' });
  });

  it('refuses characters that are not base64url, and a missing version', async () => {
    expect(await decoded('#/a/1.abc$def')).toEqual({ ok: false, kind: 'damaged', reasons: [expect.stringContaining('characters')] });
    expect(await decoded('#/a/abcdef')).toEqual({ ok: false, kind: 'damaged', reasons: ['the version number is missing'] });
  });

  it('says which version a link from another app version has', async () => {
    const fragment = (await encodeAssignment(lesson)).replace('#/a/1.', '#/a/7.');
    expect(await decoded(fragment)).toEqual({ ok: false, kind: 'other-version', reasons: ['the link has version "7"; this app opens version 1'] });
  });

  it('lists the fields of a well-formed link whose assignment is wrong', async () => {
    const edited = { ...lesson, levels: [], otherLevels: 'secret', extra: 1 } as unknown as Assignment;
    const result = await decoded(await encodeAssignment(edited), catalog);
    expect(result.ok).toBe(false);
    if (result.ok) return;
    expect(result.kind).toBe('damaged');
    expect(result.reasons).toEqual(
      expect.arrayContaining([
        expect.stringMatching(/^levels: must have at least 1/),
        expect.stringMatching(/^otherLevels: must be/),
        expect.stringMatching(/unknown field "extra"/),
      ]),
    );
  });

  it('refuses required tasks of levels outside the assignment, and duplicate levels', async () => {
    const edited: Assignment = { ...lesson, levels: ['01-introduction', '01-introduction'], requiredTasks: { 'other-level': ['x'] } };
    const result = await decoded(await encodeAssignment(edited));
    expect(result).toEqual({
      ok: false,
      kind: 'damaged',
      reasons: ['levels[1]: "01-introduction" is listed more than once', 'requiredTasks.other-level: "other-level" is not one of the assignment\'s levels'],
    });
  });

  it('lists the levels and tasks this game does not have', async () => {
    const foreign: Assignment = { ...lesson, levels: ['01-introduction', '09-caustics', '10-fog'], requiredTasks: { '01-introduction': ['orbit', 'juggle'] } };
    expect(await decoded(await encodeAssignment(foreign), catalog)).toEqual({
      ok: false,
      kind: 'unknown-levels',
      reasons: ['09-caustics', '10-fog', '01-introduction/juggle'],
    });
  });

  it('carries an optional class code and xAPI home page, checked', async () => {
    const school = { ...lesson, classCode: '3B', xapiHomePage: 'https://school.example/' };
    expect(await decoded(await encodeAssignment(school), catalog)).toEqual({ ok: true, assignment: school });
    // Without them the link and the id are the same as before the fields existed.
    expect(assignmentId({ ...school, classCode: undefined, xapiHomePage: undefined })).toBe(assignmentId(lesson));
    expect(assignmentId(school)).not.toBe(assignmentId(lesson));
    const bad = await decoded(await encodeAssignment({ ...lesson, classCode: '3 B', xapiHomePage: 'ftp://school.example' }), catalog);
    expect(bad.ok).toBe(false);
    if (!bad.ok) expect(bad.reasons.join('\n')).toMatch(/classCode[\s\S]*xapiHomePage|xapiHomePage[\s\S]*classCode/);
  });

  it('stops unpacking a link that would unpack to far more than an assignment', async () => {
    const padded = `{"version": 1, "title": "x"${' '.repeat(5 * 1024 * 1024)}}`;
    const bomb = `#/a/1.${toBase64Url(await deflate(new TextEncoder().encode(padded)))}`;
    expect(bomb.length).toBeLessThan(20_000);
    expect(await decoded(bomb, catalog)).toEqual({
      ok: false,
      kind: 'damaged',
      reasons: ['it unpacks to more than 1024 kB, more than any assignment'],
    });
  });

  it('refuses ids longer than 64 characters and more than 100 required tasks per level, quoting no long value', async () => {
    const long = 'a'.repeat(100_000);
    const tasks = Array.from({ length: 101 }, (_, i) => `t${i}`);
    const result = await decoded(
      await encodeAssignment({ ...lesson, levels: [long, '01-introduction'], requiredTasks: { [long]: ['orbit'], '01-introduction': tasks } }),
    );
    expect(result).toMatchObject({ ok: false, kind: 'damaged' });
    const reasons = result.ok ? [] : result.reasons;
    expect(reasons).toContain('levels[0]: must be at most 64 characters long');
    expect(reasons.some((reason) => /must have at most 100 items/.test(reason))).toBe(true);
    expect(Math.max(...reasons.map((reason) => reason.length))).toBeLessThan(300);
  });

  it('gives each assignment its own stable id and progress key', () => {
    expect(assignmentId(lesson)).toMatch(/^[0-9a-f]{8}$/);
    expect(assignmentId({ ...lesson })).toBe(assignmentId(lesson));
    expect(assignmentId({ ...lesson, title: 'Lesson 3' })).not.toBe(assignmentId(lesson));
    expect(assignmentProgressKey(lesson)).toBe(`${PROGRESS_KEY}.assignment.${assignmentId(lesson)}`);
  });
});

describe('base64url', () => {
  it('round-trips every byte value without padding or URL-unsafe characters', () => {
    const bytes = Uint8Array.from({ length: 256 }, (_, i) => i);
    const text = toBase64Url(bytes);
    expect(text).toMatch(/^[A-Za-z0-9_-]+$/);
    expect(fromBase64Url(text)).toEqual(bytes);
  });

  it('returns null for text that cannot be base64url', () => {
    expect(fromBase64Url('ab+c')).toBeNull();
    expect(fromBase64Url('abcde')).toBeNull();
  });
});
