/** Prints rows of [measure, value, goal] as an aligned text table. */
export function printTable(rows: [string, string, string][]): void {
  const all: [string, string, string][] = [['measure', 'value', 'goal'], ...rows];
  const widths = [0, 1, 2].map((column) => Math.max(...all.map((row) => row[column].length)));
  const line = (row: string[]) =>
    row
      .map((cell, column) => cell.padEnd(widths[column]))
      .join('  ')
      .trimEnd();
  console.log(line(all[0]));
  console.log(widths.map((w) => '-'.repeat(w)).join('  '));
  for (const row of rows) console.log(line(row));
}
