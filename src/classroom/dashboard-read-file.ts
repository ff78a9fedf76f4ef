import { msg } from '@lit/localize';
import type { FileRead } from './dashboard-record.ts';
import { readCsvExport } from './dashboard-read-csv.ts';
import { readJsonExport } from './dashboard-read-json.ts';

/** Exports larger than this are not a learner's log (a year of play is well under 5 MB). */
export const MAX_EXPORT_BYTES = 20 * 1024 * 1024;

/**
 * Reads one dropped file: a JSON or CSV export, told apart by its name and else by its
 * first character. Anything else comes back with the reason it was skipped.
 */
export function readExportFile(file: string, text: string): FileRead {
  if (text.trim() === '') return { ok: false, file, reason: msg('the file is empty') };
  if (text.includes('\u0000')) return { ok: false, file, reason: msg('not a text file (an image, a document or an archive?)') };
  const lower = file.toLowerCase();
  const looksJson = /^\s*[[{]/.test(text.replace(/^\uFEFF/, ''));
  if (lower.endsWith('.json') || (!lower.endsWith('.csv') && looksJson)) return readJsonExport(file, text);
  if (lower.endsWith('.csv') || /^\uFEFF?[\w" ]+,/.test(text)) return readCsvExport(file, text);
  return { ok: false, file, reason: msg('not a Ray Tracer Quest export (expected a .json or .csv file from the game)') };
}
