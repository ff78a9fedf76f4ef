import { z } from 'zod';
import { reasonIssue, withReason } from '../scene/scene-issues.ts';
import { kebabId } from '../quest/kebab-id.ts';
import { LOCALES } from '../quest/localized-text.ts';
import type { Assignment } from './assignment.ts';
import { CONCEPT_TEST_ORDERS } from './concept-test/concept-test-plan.ts';

/**
 * The zod schema of an Assignment, for links opened by students (assignment-link.ts): a link
 * may be hand-edited or cut short, so every field is checked before the game trusts it.
 */

/** Long enough for "Ray tracing, lesson 2: shadows and soft shadows"; short enough for a QR code. */
export const TITLE_MAX = 120;
/** More levels than the game will ever have; it only stops absurd links. */
export const LEVELS_MAX = 100;
/** A class code is a short label like a participant code ("3B", "group-2"). */
export const CLASS_CODE = /^[\p{L}\p{N}_-]{1,32}$/u;

/** A page of text: room for what is recorded, who sees it, and how to withdraw; short enough for a link. */
export const CONSENT_MAX = 2000;

/** Far more tasks than a level has; it only stops absurd links. */
export const TASKS_MAX = 100;

export const assignmentSchema = z
  .strictObject({
    version: z.literal(1),
    title: z.string().trim().min(1).max(TITLE_MAX),
    levels: z.array(kebabId()).min(1).max(LEVELS_MAX),
    requiredTasks: z.record(kebabId(), z.array(kebabId()).max(TASKS_MAX)),
    otherLevels: z.enum(['hidden', 'shown']),
    locale: z.enum(LOCALES),
    askParticipantCode: z.boolean(),
    survey: kebabId().nullable(),
    classCode: z
      .string()
      .regex(CLASS_CODE, { error: (issue) => withReason(issue, { code: 'notClassCode' }) })
      .optional(),
    xapiHomePage: z
      .url({ protocol: /^https?$/, error: (issue) => withReason(issue, { code: 'notWebAddress' }) })
      .max(200)
      .optional(),
    // Added later: an older link has none and opens as before, so the format's version stays 1.
    consent: z.string().trim().min(1).max(CONSENT_MAX).optional(),
    // Optional, so that links made before it still open (as version 1).
    conceptTest: z.enum(CONCEPT_TEST_ORDERS).optional(),
    // Optional like the two above; a question the survey does not have is ignored (survey-for-levels.ts).
    surveyQuestions: z.record(kebabId(), z.boolean()).optional(),
  })
  .superRefine((assignment, context) => {
    assignment.levels.forEach((id, index) => {
      if (assignment.levels.indexOf(id) !== index) context.addIssue(reasonIssue(['levels', index], id, { code: 'listedTwice', id }));
    });
    for (const id of Object.keys(assignment.requiredTasks)) {
      if (!assignment.levels.includes(id)) context.addIssue(reasonIssue(['requiredTasks', id], id, { code: 'notAssignmentLevel', id }));
    }
  });

// The schema and the shared type must describe the same thing: this fails to compile if they drift.
type Same<A, B> = [A] extends [B] ? ([B] extends [A] ? true : false) : false;
const inSync: Same<z.output<typeof assignmentSchema>, Assignment> = true;
void inSync;
