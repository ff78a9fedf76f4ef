// The ray legend's key for "Colour by time" (issue 37: the option had no legend): shown only
// while the option is on, from "shutter opens" to "shutter closes", in the rays' own colours.
import { nothing, type TemplateResult } from 'lit';
import { describe, expect, it } from 'vitest';
import { timeKey } from '../../../../src/ui/lab/panels/time-key.ts';
import { timeGradient } from '../../../../src/view/time-colors.ts';

/** Every value a template holds, nested templates and style maps included, as text. */
function values(value: unknown): string[] {
  if (Array.isArray(value)) return value.flatMap(values);
  if (typeof value === 'object' && value !== null && 'strings' in value) return (value as TemplateResult).values.flatMap(values);
  if (typeof value === 'object' && value !== null && 'values' in value) return values((value as { values: unknown[] }).values);
  return [typeof value === 'object' ? JSON.stringify(value) : String(value)];
}

describe('the time key of the ray legend', () => {
  it('is not there while Colour by time is off', () => {
    expect(timeKey(false)).toBe(nothing);
  });

  it('names both ends of the open shutter and paints the rays’ ramp between them while it is on', () => {
    const key = timeKey(true);
    expect(key).not.toBe(nothing);
    const shown = values(key);
    expect(shown).toContain('shutter opens');
    expect(shown).toContain('shutter closes');
    expect(shown.join(' ')).toContain(timeGradient());
    // Read out without the colours alone: the label says which end is which.
    expect(shown.some((text) => /dark violet when the shutter opens.*yellow when it closes/.test(text))).toBe(true);
  });
});
