import { deflateSync, strToU8 } from 'fflate';
import { describe, expect, it } from 'vitest';
import { readClassFiles } from '../../src/classroom/dashboard-class.ts';
import { MAX_EXPORT_BYTES } from '../../src/classroom/dashboard-read-file.ts';
import { classLearners } from '../../src/classroom/dashboard-learners.ts';
import type { ExportInput } from '../../src/classroom/export-context.ts';
import { exportJson, type QuestExport } from '../../src/classroom/export-json.ts';
import { decodeResultsCode, findResultsCodes, RESULTS_CODE_PREFIX, resultsCode } from '../../src/classroom/results-code.ts';
import { newProgress } from '../../src/quest/progress.ts';
import { CLASS_ASSIGNMENT, simulatedExport } from '../support/class-exports.ts';

/** The export input that made a simulated learner's file. */
function inputOf(file: QuestExport): ExportInput {
  const clock = { monotonicMs: () => 0, wallMs: () => Date.parse(file.events.startedAt) };
  return {
    progress: { ...newProgress(clock), log: file.events },
    participant: file.participant,
    installId: file.learner.installId,
    attemptId: file.learner.attemptId,
    assignment: CLASS_ASSIGNMENT,
    survey: file.survey,
    exportedAt: file.exportedAt,
    appVersion: file.appVersion,
  };
}

const learners = Array.from({ length: 6 }, (_, index) => inputOf(simulatedExport(index)));

describe('results code', () => {
  it('is one line of base64url text after the prefix', () => {
    const code = resultsCode(learners[0]);
    expect(code.startsWith(RESULTS_CODE_PREFIX)).toBe(true);
    expect(code.slice(RESULTS_CODE_PREFIX.length)).toMatch(/^[A-Za-z0-9_-]+$/);
    // Much shorter than the results file it stands for.
    expect(code.length).toBeLessThan(exportJson(learners[0]).length / 4);
  });

  it('gives the dashboard the same learner, tasks and survey as the results file', () => {
    const fromFiles = classLearners(readClassFiles(learners.map((input, index) => ({ name: `file-${index}.json`, text: exportJson(input) }))).records);
    const pasted = learners.map((input) => resultsCode(input)).join('\n');
    const fromCodes = classLearners(
      readClassFiles(findResultsCodes(pasted).map((code, index) => ({ name: `code-${index}`, text: decodeResultsCode(code)! }))).records,
    );
    expect(fromCodes).toHaveLength(6);
    const strip = ({ file, files, parts, ...learner }: (typeof fromFiles)[number]) => ({
      ...learner,
      parts: parts.length,
      files: files.length,
      file: file !== '',
    });
    expect(fromCodes.map(strip)).toEqual(fromFiles.map(strip));
  });

  it('is found in any pasted text: a spreadsheet column, a CSV of form answers', () => {
    const [a, b] = [resultsCode(learners[0]), resultsCode(learners[1])];
    expect(findResultsCodes(`Timestamp,Name,Code\r\n"6-12-2026 10:01","Anna","${a}"\r\n"6-12-2026 10:02","Bas",${b}\r\n`)).toEqual([a, b]);
    expect(findResultsCodes('no code here')).toEqual([]);
  });

  it('says a code that was cut off while copying is damaged', () => {
    const code = resultsCode(learners[0]);
    expect(decodeResultsCode(code.slice(0, code.length - 20))).toBeNull();
    expect(decodeResultsCode('RTQ1.!!!')).toBeNull();
    expect(decodeResultsCode(code.replace(RESULTS_CODE_PREFIX, 'XYZ.'))).toBeNull();
  });

  it('does not unpack a code past the dashboard file limit', () => {
    const bomb = deflateSync(strToU8(' '.repeat(MAX_EXPORT_BYTES + 1024)), { level: 9 });
    const code = RESULTS_CODE_PREFIX + Buffer.from(bomb).toString('base64url');
    expect(code.length).toBeLessThan(100_000);
    expect(decodeResultsCode(code)).toBeNull();
  });
});
