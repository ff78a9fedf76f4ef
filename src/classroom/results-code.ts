import { deflateSync, Inflate, strFromU8, strToU8 } from 'fflate';
import { buildExport, type QuestExport } from './export-json.ts';
import type { ExportInput } from './export-context.ts';
import { MAX_EXPORT_BYTES } from './dashboard-read-file.ts';

/**
 * The results code: a pupil's results as one line of text, for a school without a learning
 * platform that takes files. The pupil copies it into a form the teacher chose (a Google or
 * Microsoft form, a Magister or Teams assignment, an e-mail), the teacher pastes the
 * collected codes into the dashboard, which reads them exactly as it reads the results file.
 *
 * `RTQ1.` then the export as compact JSON, deflated (RFC 1951, fflate) and written in
 * base64url (RFC 4648 §5): letters, digits, `-` and `_`, so that no form, spreadsheet or
 * mail program changes it, and a double click selects all of it. The code holds what the
 * dashboard reads (who, which assignment, the event log, the survey); the per-task rows and
 * the progress summary are left out, since both are read back from the event log.
 */

export const RESULTS_CODE_PREFIX = 'RTQ1.';

/** Every code in a pasted text (one per line, or a column copied from a spreadsheet). */
const CODE_PATTERN = /RTQ1\.[A-Za-z0-9_-]+/g;

export function resultsCode(input: ExportInput): string {
  const { format, version, appVersion, exportedAt, participant, learner, assignment, events, survey } = buildExport(input);
  const slim: Partial<QuestExport> = { format, version, appVersion, exportedAt, participant, learner, assignment, events, survey };
  return RESULTS_CODE_PREFIX + toBase64Url(deflateSync(strToU8(JSON.stringify(slim)), { level: 9 }));
}

/** The codes found in a pasted text, in order. */
export function findResultsCodes(text: string): string[] {
  return text.match(CODE_PATTERN) ?? [];
}

/**
 * The export's JSON text of one code, or null when it is damaged (cut off while copying,
 * or not a code). Inflating stops past the dashboard's file limit, so a hostile code cannot
 * make the page unpack gigabytes.
 */
export function decodeResultsCode(code: string): string | null {
  if (!code.startsWith(RESULTS_CODE_PREFIX)) return null;
  const bytes = fromBase64Url(code.slice(RESULTS_CODE_PREFIX.length));
  if (!bytes) return null;
  const chunks: Uint8Array[] = [];
  let size = 0;
  let ended = false;
  try {
    const inflater = new Inflate((chunk, final) => {
      size += chunk.length;
      if (size > MAX_EXPORT_BYTES) throw new Error('too large');
      chunks.push(chunk);
      ended ||= final;
    });
    inflater.push(bytes, true);
  } catch {
    return null;
  }
  if (!ended) return null;
  const all = new Uint8Array(size);
  let offset = 0;
  for (const chunk of chunks) {
    all.set(chunk, offset);
    offset += chunk.length;
  }
  return strFromU8(all);
}

function toBase64Url(bytes: Uint8Array): string {
  let binary = '';
  // In slices: String.fromCharCode with a whole log's bytes as arguments overflows the stack.
  for (let i = 0; i < bytes.length; i += 0x8000) binary += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
  return btoa(binary).replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');
}

function fromBase64Url(text: string): Uint8Array | null {
  try {
    const binary = atob(text.replace(/-/g, '+').replace(/_/g, '/'));
    return Uint8Array.from(binary, (char) => char.charCodeAt(0));
  } catch {
    return null;
  }
}
