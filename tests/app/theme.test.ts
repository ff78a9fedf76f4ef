import { afterEach, describe, expect, it, vi } from 'vitest';
import { savedTheme } from '../../src/app/theme.ts';

describe('the saved theme', () => {
  afterEach(() => vi.unstubAllGlobals());

  it('is the remembered choice, or system for anything else', () => {
    const items = new Map([['rtq.theme', 'dark']]);
    vi.stubGlobal('localStorage', { getItem: (key: string) => items.get(key) ?? null });
    expect(savedTheme()).toBe('dark');
    items.set('rtq.theme', '<script>');
    expect(savedTheme()).toBe('system');
  });

  it('is system when the browser blocks storage (reading it throws)', () => {
    vi.stubGlobal('localStorage', {
      getItem: () => {
        throw new DOMException('The operation is insecure.', 'SecurityError');
      },
    });
    expect(savedTheme()).toBe('system');
  });
});
