import { deflateSync, inflateSync, strFromU8, strToU8 } from 'fflate';
import { PROGRESS_KIND, PROGRESS_VERSION, type Progress } from '../../quest/progress.ts';
import { parseProgress } from '../../quest/progress-store.ts';
import type { ScormVersion } from './lms-api.ts';

/**
 * The learner's progress in the platform's `suspend_data`, so that a pupil who comes back on
 * another computer (or after the browser's storage was cleared) continues where they were.
 *
 * The text is `rtq1.` and the progress's JSON, deflated (fflate: RFC 1951) and written in
 * base64: a level's log of about a hundred events shrinks about eightfold. Scenes are left
 * out (the sandbox, the level's scene as the learner left it): they are the largest part and
 * a level opens again with its own scene.
 *
 * The room is the platform's: SCORM 1.2 guarantees 4096 characters (RTE 1.2 §3.4.4,
 * cmi.suspend_data CMIString4096), SCORM 2004 4th edition 64000 (RTE 4th ed. §4.2.23).
 * When the whole progress does not fit, the event log is left out and only the completed
 * tasks, their points and the badges are kept (`tasks`): a resumed pupil has their levels
 * and score, but the time and hints of the earlier sessions stay only in that browser's
 * storage and its exports. When not even that fits, nothing is written (`none`) and the
 * platform keeps the last that did fit: docs/classroom.md says so to teachers.
 */

export const SUSPEND_DATA_LIMIT: Readonly<Record<ScormVersion, number>> = { '1.2': 4096, '2004': 64000 };

const PREFIX = 'rtq1.';

/** How much of the progress the text holds. */
export type SuspendedPart = 'full' | 'tasks' | 'none';

interface Suspended {
  levels: Progress['levels'];
  badges: Progress['badges'];
  log?: Progress['log'];
  epoch?: string;
}

function pack(value: Suspended): string {
  const bytes = deflateSync(strToU8(JSON.stringify(value)), { level: 9 });
  let binary = '';
  for (const byte of bytes) binary += String.fromCharCode(byte);
  return PREFIX + btoa(binary);
}

/** The most of `progress` that fits in `limit` characters, and which part that is. */
export function suspendProgress(progress: Progress, limit: number): { text: string; part: SuspendedPart } {
  const tasks: Suspended = { levels: progress.levels, badges: progress.badges, ...(progress.epoch === undefined ? {} : { epoch: progress.epoch }) };
  const full = pack({ ...tasks, log: progress.log });
  if (full.length <= limit) return { text: full, part: 'full' };
  const some = pack(tasks);
  if (some.length <= limit) return { text: some, part: 'tasks' };
  return { text: '', part: 'none' };
}

/**
 * Progress from suspend data, checked like a saved file (progress-store.ts): null when the
 * text is not ours or is damaged. Without a log (`tasks`), the log starts empty at `nowIso`.
 */
export function resumeProgress(text: string, nowIso: string): Progress | null {
  if (!text.startsWith(PREFIX)) return null;
  let suspended: Partial<Suspended>;
  try {
    const binary = atob(text.slice(PREFIX.length));
    const bytes = Uint8Array.from(binary, (char) => char.charCodeAt(0));
    suspended = JSON.parse(strFromU8(inflateSync(bytes))) as Partial<Suspended>;
  } catch {
    return null;
  }
  const parsed = parseProgress({
    kind: PROGRESS_KIND,
    version: PROGRESS_VERSION,
    levels: suspended.levels,
    badges: suspended.badges,
    sandbox: null,
    current: null,
    log: suspended.log ?? { startedAt: nowIso, events: [] },
    ...(suspended.epoch === undefined ? {} : { epoch: suspended.epoch }),
  });
  return parsed.ok ? parsed.progress : null;
}
