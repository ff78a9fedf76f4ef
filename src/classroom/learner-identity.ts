import type { KeyValueStorage } from '../quest/progress-store.ts';

/**
 * Who a learner is and which playthrough an export belongs to, so that the dashboard can
 * tell one student who pressed every download button from several students.
 *
 * - The install id is a random UUID kept in this browser's storage: the same for every
 *   assignment and free play on this computer, until the browser's data is cleared. It is
 *   made only for learners without a participant code: with a code it would be a second,
 *   device-wide identifier that links a pupil's work across assignments and classes, which
 *   a pseudonymous study must not hold (AVG/GDPR art. 5(1)(c), data minimisation).
 * - The attempt id is a random UUID per playthrough (one saved progress): kept with the
 *   progress, the same in every file exported from it, new after "start again".
 * - The learner id names the person: the participant code when one was asked, else the
 *   install id (one browser, one learner). Together with the assignment id it is unique.
 *
 * Random ids, not hashes of anything personal: nothing about the learner can be read
 * from them.
 */

export interface LearnerIdentity {
  installId: string;
  attemptId: string;
}

export const INSTALL_ID_KEY = 'rtq.install-id';

/** Codes are short labels a teacher hands out ("A17", "group-3"): nothing personal is asked. */
export const PARTICIPANT_CODE = /^[\p{L}\p{N}_-]{1,32}$/u;

const UUID = /^[0-9a-f]{8}-[0-9a-f]{4}-4[0-9a-f]{3}-[89ab][0-9a-f]{3}-[0-9a-f]{12}$/;

export function isUuid(text: unknown): text is string {
  return typeof text === 'string' && UUID.test(text);
}

/**
 * A version 4 UUID (RFC 9562 §5.4). Made from crypto.getRandomValues, not randomUUID:
 * randomUUID exists only on https and localhost pages, and a school may serve the app
 * over plain http or open it from a USB stick.
 */
export function randomUuid(): string {
  const bytes = crypto.getRandomValues(new Uint8Array(16));
  bytes[6] = (bytes[6] & 0x0f) | 0x40;
  bytes[8] = (bytes[8] & 0x3f) | 0x80;
  const hex = [...bytes].map((byte) => byte.toString(16).padStart(2, '0')).join('');
  return `${hex.slice(0, 8)}-${hex.slice(8, 12)}-${hex.slice(12, 16)}-${hex.slice(16, 20)}-${hex.slice(20)}`;
}

/** This browser's install id, made and kept on first use; a storage that refuses gives one for this visit. */
export function installId(storage: KeyValueStorage): string {
  try {
    const saved = storage.getItem(INSTALL_ID_KEY);
    if (isUuid(saved)) return saved;
  } catch {
    // Blocked storage: a fresh id below, for this visit.
  }
  const made = randomUuid();
  try {
    storage.setItem(INSTALL_ID_KEY, made);
  } catch {
    // Kept for this visit only; the progress store reports the storage problem.
  }
  return made;
}

/**
 * The install id an export carries: none ('') when the learner has a participant code, and
 * then none is made or kept in the browser either; else this browser's (installId).
 */
export function exportInstallId(participant: string | null, storage: KeyValueStorage): string {
  return participant ? '' : installId(storage);
}

/** The learner id of the exports: the participant code, else `install:<install id>`. */
export function learnerId(participant: string | null, install: string): string {
  return participant ? participant : `install:${install}`;
}
