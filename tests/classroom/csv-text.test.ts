import { describe, expect, it } from 'vitest';
import { csvField, csvText, parseCsv } from '../../src/classroom/csv-text.ts';

describe('CSV fields a spreadsheet would run as formulas', () => {
  it('start with an apostrophe: the ASCII signs, a tab and a carriage return', () => {
    for (const cell of ['=1+1', '+31 6', '-2', '@SUM(A1)', '\tx', '\rx']) expect(csvField(cell)).toMatch(/^"?'/);
  });

  it('also in their full-width and small forms (＝ ＋ － ＠, ﹦ ﹢ ﹣ ﹫)', () => {
    for (const cell of ['＝HYPERLINK("http://x","y")', '＋1', '－1', '＠A1', '﹦1', '﹢1', '﹣1', '﹫A1']) {
      expect(csvField(cell), cell).toBe(cell.includes(',') || cell.includes('"') ? `"'${cell.replaceAll('"', '""')}"` : `'${cell}`);
    }
  });

  it('leaves other text and numbers as they are, and reads back what it wrote', () => {
    expect(csvField('A17')).toBe('A17');
    expect(csvField('ｅｑｕａｌ')).toBe('ｅｑｕａｌ');
    expect(csvField(-2)).toBe('-2');
    const text = csvText([['＝1+1', 'plain', 'a,b']]);
    expect(parseCsv(text)).toEqual({ ok: true, rows: [["'＝1+1", 'plain', 'a,b']] });
  });
});
