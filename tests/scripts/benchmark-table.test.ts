import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { benchmarkTable, PAGE_PATH, readResults, TABLE_END, TABLE_START, withBenchmarkTable } from '../../scripts/benchmark-table.ts';

describe("docs/benchmarks.md's table", () => {
  const page = readFileSync(PAGE_PATH, 'utf8');
  const results = readResults();

  it('is what scripts/benchmark-table.ts writes from bench/results.json (run it after npm run bench)', () => {
    expect(page).toBe(withBenchmarkTable(page, results));
  });

  it('shows the reference render of results.json, and changes with it', () => {
    expect(benchmarkTable(results)).toContain(`**${results.referenceMs['2']} ms**`);
    const other = { ...results, referenceMs: { ...results.referenceMs, 2: results.referenceMs['2'] + 1 } };
    expect(withBenchmarkTable(page, other)).not.toBe(page);
  });

  it('sits between exactly one pair of markers', () => {
    expect(page.split(TABLE_START)).toHaveLength(2);
    expect(page.split(TABLE_END)).toHaveLength(2);
  });
});
