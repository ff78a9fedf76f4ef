/**
 * `npm run fuzz`: 10,000 generated cases for every parser of outside input (fuzz-targets.ts),
 * and a table of what they came to. Exits 1 when a case crashed or hung. `npm run fuzz -- 500`
 * runs another number of cases.
 */
import { fuzz, fuzzTargets, HANG_MS, type FuzzTally } from './fuzz-targets.ts';

const cases = Number(process.argv[2] ?? 10_000);
const rows: FuzzTally[] = [];
for (const target of await fuzzTargets()) {
  const started = performance.now();
  const tally = await fuzz(target, cases);
  rows.push(tally);
  process.stderr.write(`${target.name}: ${Math.round((performance.now() - started) / 1000)} s\n`);
}

const header = ['parser', 'cases', 'clean errors', 'accepted', 'crashes', `hangs (>${HANG_MS} ms)`, 'slowest ms'];
const table = [header, ...rows.map((row) => [row.name, row.cases, row.refused, row.accepted, row.crashed, row.hangs, row.slowestMs.toFixed(1)].map(String))];
const widths = header.map((_, column) => Math.max(...table.map((row) => row[column].length)));
for (const row of table)
  process.stdout.write(`${row.map((cell, column) => (column === 0 ? cell.padEnd(widths[column]) : cell.padStart(widths[column]))).join('  ')}\n`);
for (const row of rows) if (row.firstProblem) process.stdout.write(`${row.name}: ${row.firstProblem}\n`);
process.exitCode = rows.some((row) => row.crashed > 0 || row.hangs > 0) ? 1 : 0;
