/**
 * Participant codes as one learner: `5h2-03`, ` 5H2-03 ` and `5H2-03` are the same pupil.
 * Every place a code comes in (the code dialog, the dashboard's files, a class list) passes
 * it through `normalParticipantCode`, so a code typed in lower case never becomes a second
 * learner. Capitals, because the codes a teacher hands out are printed that way.
 */

/** The code as the app keeps and compares it: trimmed, composed (NFC), in capitals. */
export function normalParticipantCode(code: string): string {
  return code.trim().normalize('NFC').toUpperCase();
}

/**
 * A learner id of an export as the dashboard compares it: the participant code (the id an
 * export gives a learner with a code, learner-identity.ts learnerId) in its normal form; any
 * other id (`install:<uuid>` for a learner without a code, `file:<name>`) as it is.
 */
export function learnerKey(id: string, participant: string): string {
  const code = normalParticipantCode(participant);
  return code !== '' && normalParticipantCode(id) === code ? code : id;
}

/** The most code slips a handout makes: a large lecture, not an accident of typing. */
export const MAX_NUMBERED_CODES = 300;

/**
 * `count` codes for one class: `<prefix>-01` … `<prefix>-30`, numbered with as many digits as
 * the largest number needs (at least two), in the normal form. An empty prefix gives `P-01` ….
 */
export function numberedCodes(prefix: string, count: number): string[] {
  const start = normalParticipantCode(prefix).replace(/[^\p{L}\p{N}_-]+/gu, '') || 'P';
  const total = Math.max(0, Math.min(MAX_NUMBERED_CODES, Math.floor(count)));
  const digits = Math.max(2, String(total).length);
  return Array.from({ length: total }, (_, index) => `${start}-${String(index + 1).padStart(digits, '0')}`);
}
