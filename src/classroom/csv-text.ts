/**
 * CSV text (RFC 4180) in both directions: the dashboard reads learners' CSV exports and
 * writes the class's combined CSV. Fields with a comma, quote or line break are quoted;
 * a field that a spreadsheet would run as a formula (=, +, -, @ first) is prefixed with
 * an apostrophe, because participant codes and free text are typed by learners. The check
 * reads the field as NFKC (Unicode compatibility form), so that the full-width and small
 * forms (＝ ＋ － ＠, ﹦ ﹢ ﹣ ﹫), which some spreadsheets read as the ASCII signs, are
 * caught too.
 */

const NEEDS_QUOTES = /[",\r\n]/;
const FORMULA_START = /^[=+\-@\t\r]/;

/**
 * One field, escaped; numbers are written as they are (a negative number is not a formula).
 * `quoted`: always in quotes, for identifiers that must stay text ("007").
 */
export function csvField(value: string | number | boolean | null, quoted = false): string {
  if (value === null) return '';
  if (typeof value !== 'string') return String(value);
  const safe = FORMULA_START.test(value.normalize('NFKC')) ? `'${value}` : value;
  return quoted || NEEDS_QUOTES.test(safe) ? `"${safe.replaceAll('"', '""')}"` : safe;
}

type Row = readonly (string | number | boolean | null)[];

/** Rows to CSV text with CRLF line ends (what spreadsheets expect). */
export function csvText(rows: readonly Row[]): string {
  return rows.map((row) => row.map((value) => csvField(value)).join(',')).join('\r\n') + '\r\n';
}

/** A header and its rows, the non-empty cells of the `quoted` columns in quotes. */
export function csvTable(header: readonly string[], rows: readonly Row[], quoted: ReadonlySet<string>): string {
  const quote = header.map((name) => quoted.has(name));
  const lines = rows.map((row) => row.map((value, column) => csvField(value, quote[column] && value !== '')).join(','));
  return [header.map((name) => csvField(name)).join(','), ...lines].join('\r\n') + '\r\n';
}

/** A failure names the line of the quote that is never closed, and says so in English for scripts and tests. */
export type CsvRead = { ok: true; rows: string[][] } | { ok: false; error: string; openQuoteLine: number };

/** Splits CSV text into rows of fields; an unclosed quote is an error with its line. */
export function parseCsv(text: string): CsvRead {
  const rows: string[][] = [];
  let row: string[] = [];
  let field = '';
  let quoted = false;
  let quoteLine = 0;
  let line = 1;
  const source = text.replace(/^\uFEFF/, '');
  for (let i = 0; i < source.length; i++) {
    const char = source[i];
    if (quoted) {
      if (char === '"' && source[i + 1] === '"') {
        field += '"';
        i++;
      } else if (char === '"') quoted = false;
      else {
        if (char === '\n') line++;
        field += char;
      }
    } else if (char === '"' && field === '') {
      quoted = true;
      quoteLine = line;
    } else if (char === ',') {
      row.push(field);
      field = '';
    } else if (char === '\n' || char === '\r') {
      if (char === '\r' && source[i + 1] === '\n') i++;
      row.push(field);
      rows.push(row);
      row = [];
      field = '';
      line++;
    } else field += char;
  }
  if (quoted) return { ok: false, error: `a quoted field that starts on line ${quoteLine} is never closed`, openQuoteLine: quoteLine };
  if (field !== '' || row.length > 0) {
    row.push(field);
    rows.push(row);
  }
  return { ok: true, rows: rows.filter((fields) => fields.some((value) => value !== '')) };
}
