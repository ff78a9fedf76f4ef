import type { TemplateResult } from 'lit';
import { describe, expect, it } from 'vitest';
import { levelText } from '../../../src/ui/game/level-text.ts';

/** What a template shows, as the markup it stands for: its values written in, a nested template's tags kept. */
function shown(value: unknown): string {
  if (Array.isArray(value)) return value.map(shown).join('');
  if (typeof value === 'object' && value !== null && 'strings' in value) {
    const template = value as TemplateResult;
    return template.strings.reduce((text, piece, index) => text + piece + (index < template.values.length ? shown(template.values[index]) : ''), '');
  }
  return `[${String(value)}]`;
}

describe('a level text in the task column', () => {
  it('shows each marked name in <strong>, in the learner’s language', () => {
    const text = { en: 'Press **Render image** at the top.', nl: 'Druk bovenaan op **Beeld renderen**.' };
    expect(shown(levelText(text, 'en'))).toBe('[Press ]<strong>[Render image]</strong>[ at the top.]');
    expect(shown(levelText(text, 'nl'))).toBe('[Druk bovenaan op ]<strong>[Beeld renderen]</strong>[.]');
  });

  it('hands every piece to lit as a value, so markup in a level file is shown as text', () => {
    // Brackets mark a value: lit escapes it; only the <strong> tags are the app's own markup.
    expect(shown(levelText('A <img src=x onerror=alert(1)> and **<b>Save</b>**', 'en'))).toBe(
      '[A <img src=x onerror=alert(1)> and ]<strong>[<b>Save</b>]</strong>',
    );
  });
});
