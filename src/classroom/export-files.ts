import type { ExportInput } from './export-context.ts';
import { exportCsv } from './export-csv.ts';
import { exportJson } from './export-json.ts';
import { exportXapi } from './export-xapi.ts';

export { resultsCode } from './results-code.ts';

/** The formats a learner can download their results in. */
export type ExportFormat = 'csv' | 'json' | 'xapi';

/**
 * Each format's file: its extension, type and text. A module of its own, loaded when a
 * learner hands in (rt-export-menu.ts): the exporters and the results code's compression are
 * not needed before.
 */
export const EXPORT_FILES: Record<ExportFormat, { extension: string; type: string; text: (input: ExportInput) => string }> = {
  csv: { extension: 'csv', type: 'text/csv;charset=utf-8', text: exportCsv },
  json: { extension: 'json', type: 'application/json', text: exportJson },
  xapi: { extension: 'xapi.json', type: 'application/json', text: (input) => `${JSON.stringify(exportXapi(input), null, 2)}\n` },
};
