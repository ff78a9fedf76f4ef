import { attemptRows, CSV_COLUMNS } from './attempt-rows.ts';
import { csvText } from './csv-text.ts';
import { readExportFile } from './dashboard-read-file.ts';
import type { ClassRecord, SkippedFile } from './dashboard-record.ts';

/**
 * A class's dropped files, read: the records that count and the files skipped with their
 * reason. The same export dropped twice (or copied under another name) counts once.
 */
export interface ClassFiles {
  records: ClassRecord[];
  skipped: SkippedFile[];
}

export interface DroppedFile {
  name: string;
  text: string;
}

/** Reads every file; adds to `earlier` (files dropped before) so that drops can be repeated. */
export function readClassFiles(files: readonly DroppedFile[], earlier: ClassFiles = { records: [], skipped: [] }, seen = new Map<string, string>()): ClassFiles {
  const records = [...earlier.records];
  const skipped = [...earlier.skipped];
  for (const { name, text } of files) {
    const first = seen.get(text);
    if (first !== undefined) {
      skipped.push({ file: name, reason: `the same export as ${first}, counted once` });
      continue;
    }
    const read = readExportFile(name, text);
    if (read.ok) {
      seen.set(text, name);
      records.push(read.record);
    } else skipped.push({ file: read.file, reason: read.reason });
  }
  return { records, skipped };
}

/** The combined CSV: the learners' CSV export's columns and rows, then the file each row came from. */
export function combinedCsv(records: readonly ClassRecord[]): string {
  const rows = records.flatMap((record) => attemptRows(record, record.attempts).map((row) => [...row, record.file]));
  return csvText([[...CSV_COLUMNS, 'file'], ...rows]);
}
