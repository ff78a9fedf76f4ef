import { describe, expect, it } from 'vitest';
import type { Assignment } from '../../src/classroom/assignment.ts';
import { assignmentSchema, CONSENT_MAX } from '../../src/classroom/assignment-schema.ts';
import { consentText, defaultConsentText } from '../../src/classroom/consent-text.ts';

const assignment: Assignment = {
  version: 1,
  title: 'Lesson',
  levels: ['01-introduction'],
  requiredTasks: {},
  otherLevels: 'hidden',
  locale: 'nl',
  askParticipantCode: true,
  survey: null,
};

describe('information before the start', () => {
  it("is the teacher's text, or else the default that says what is recorded, who sees it, that it is voluntary and how to withdraw", () => {
    expect(consentText({ ...assignment, consent: 'Ons eigen verhaal.' })).toBe('Ons eigen verhaal.');
    const text = consentText(assignment);
    expect(text).toBe(defaultConsentText());
    for (const part of ['What is recorded', 'Who sees it', 'voluntary', 'Withdraw and delete my data']) expect(text).toContain(part);
    expect(text.split('\n\n')).toHaveLength(3);
  });

  it('is optional in the assignment: older links without it still open; an empty or overlong text is refused', () => {
    expect(assignmentSchema.safeParse(assignment).success).toBe(true);
    expect(assignmentSchema.safeParse({ ...assignment, consent: 'Lees dit.' }).success).toBe(true);
    expect(assignmentSchema.safeParse({ ...assignment, consent: '   ' }).success).toBe(false);
    expect(assignmentSchema.safeParse({ ...assignment, consent: 'x'.repeat(CONSENT_MAX + 1) }).success).toBe(false);
  });
});
