import { describe, expect, it } from 'vitest';
import { gestureHelp, keyCommand, type KeyPress, keyHelp } from '../../src/view/view-commands.ts';

function press(key: string, modifiers: Partial<KeyPress> = {}): KeyPress {
  return { key, shiftKey: false, ctrlKey: false, altKey: false, metaKey: false, ...modifiers };
}

describe('the view’s keys', () => {
  it('orbit with arrows and pan with Shift+arrows, in the camera’s terms (right and up positive)', () => {
    expect(keyCommand(press('ArrowRight'), 'view')).toEqual({ kind: 'orbit', dxDeg: 5, dyDeg: 0 });
    expect(keyCommand(press('ArrowDown'), 'view')).toEqual({ kind: 'orbit', dxDeg: 0, dyDeg: -5 });
    expect(keyCommand(press('ArrowLeft', { shiftKey: true }), 'view')).toEqual({ kind: 'pan', dx: -0.05, dy: 0 });
    expect(keyCommand(press('ArrowUp', { shiftKey: true }), 'view')).toEqual({ kind: 'pan', dx: 0, dy: 0.05 });
  });

  it('step the selection in the gizmo’s mode while its handles are shown, Shift for a big step, Page Up/Down for depth', () => {
    expect(keyCommand(press('ArrowRight'), 'selection')).toEqual({ kind: 'nudge', direction: 'right', big: false });
    expect(keyCommand(press('ArrowDown', { shiftKey: true }), 'selection')).toEqual({ kind: 'nudge', direction: 'down', big: true });
    expect(keyCommand(press('PageUp'), 'selection')).toEqual({ kind: 'nudge', direction: 'farther', big: false });
    expect(keyCommand(press('PageDown'), 'selection')).toEqual({ kind: 'nudge', direction: 'nearer', big: false });
    // Page Up/Down scroll the page as usual when no selection takes them.
    expect(keyCommand(press('PageUp'), 'view')).toBeNull();
  });

  it('go to the next pixel of the camera’s screen while one is chosen (y down, as rows count); Shift still pans', () => {
    expect(keyCommand(press('ArrowUp'), 'pixel')).toEqual({ kind: 'pixel-step', dx: 0, dy: -1 });
    expect(keyCommand(press('ArrowRight'), 'pixel')).toEqual({ kind: 'pixel-step', dx: 1, dy: 0 });
    expect(keyCommand(press('ArrowRight', { shiftKey: true }), 'pixel')).toEqual({ kind: 'pan', dx: 0.05, dy: 0 });
    expect(keyCommand(press('p'), 'view')).toEqual({ kind: 'toggle-pixel' });
  });

  it('zoom in with + (or =, unshifted on most keyboards) and out with −', () => {
    expect(keyCommand(press('+'), 'view')).toEqual({ kind: 'zoom', factor: 1.1 });
    expect(keyCommand(press('='), 'view')).toEqual({ kind: 'zoom', factor: 1.1 });
    expect(keyCommand(press('-'), 'view')).toEqual({ kind: 'zoom', factor: 1 / 1.1 });
  });

  it('switch gizmo modes with T, R, S in either case, and local/world axes with L', () => {
    expect(keyCommand(press('t'), 'view')).toEqual({ kind: 'gizmo-mode', mode: 'translate' });
    expect(keyCommand(press('R', { shiftKey: true }), 'view')).toEqual({ kind: 'gizmo-mode', mode: 'rotate' });
    expect(keyCommand(press('s'), 'selection')).toEqual({ kind: 'gizmo-mode', mode: 'scale' });
    expect(keyCommand(press('l'), 'selection')).toEqual({ kind: 'toggle-space' });
  });

  it('never take Tab, with or without a selection: keyboard users can always leave the view (no focus trap)', () => {
    for (const arrows of ['view', 'selection', 'pixel'] as const) {
      expect(keyCommand(press('Tab'), arrows)).toBeNull();
      expect(keyCommand(press('Tab', { shiftKey: true }), arrows)).toBeNull();
    }
  });

  it('leave the browser’s and the app’s shortcuts alone (Ctrl+S saves, Alt+arrows go back)', () => {
    expect(keyCommand(press('s', { ctrlKey: true }), 'selection')).toBeNull();
    expect(keyCommand(press('ArrowLeft', { altKey: true }), 'selection')).toBeNull();
    expect(keyCommand(press('r', { metaKey: true }), 'selection')).toBeNull();
    expect(keyCommand(press('x'), 'selection')).toBeNull();
  });

  it('delete, escape, fly, select next/previous and help', () => {
    expect(keyCommand(press('Delete'), 'selection')).toEqual({ kind: 'delete' });
    expect(keyCommand(press('Backspace'), 'selection')).toEqual({ kind: 'delete' });
    expect(keyCommand(press('Escape'), 'selection')).toEqual({ kind: 'escape' });
    expect(keyCommand(press('f'), 'view')).toEqual({ kind: 'fly' });
    expect(keyCommand(press('n'), 'view')).toEqual({ kind: 'select-next', step: 1 });
    expect(keyCommand(press('N', { shiftKey: true }), 'view')).toEqual({ kind: 'select-next', step: -1 });
    expect(keyCommand(press('?', { shiftKey: true }), 'view')).toEqual({ kind: 'help' });
    expect(keyCommand(press('g'), 'view')).toEqual({ kind: 'toggle-snap' });
    expect(keyCommand(press('z'), 'view')).toEqual({ kind: 'show-pixel-rays' });
  });

  it('are all in the help panel, and every single key the help names does something', () => {
    const printed = keyHelp().flatMap((row) => row.keys);
    const asKey: Record<string, string> = {
      '←': 'ArrowLeft',
      '→': 'ArrowRight',
      '↑': 'ArrowUp',
      '↓': 'ArrowDown',
      '−': '-',
      Esc: 'Escape',
      'Page Up': 'PageUp',
      'Page Down': 'PageDown',
    };
    // Tab is the browser's (the help says so); every other key is the view's, with a selection or without.
    for (const label of printed.filter((key) => !key.includes('+ ') && key !== 'Shift' && key !== 'Tab')) {
      const key = asKey[label] ?? label;
      expect(keyCommand(press(key), 'selection') ?? keyCommand(press(key), 'view'), label).not.toBeNull();
    }
    // Every command a key gives appears in the help (by its key).
    for (const key of ['ArrowUp', 'PageUp', '+', '-', 't', 'r', 's', 'g', 'l', 'p', 'n', 'Delete', 'Escape', 'f', 'z', '?']) {
      const shown = key.length === 1 ? key.toUpperCase() : { ArrowUp: '↑', PageUp: 'Page Up', Delete: 'Delete', Escape: 'Esc' }[key];
      expect(
        printed.some((label) => label === shown || (key === '-' && label === '−')),
        key,
      ).toBe(true);
    }
    expect(printed).toContain('Tab');
    expect(gestureHelp().length).toBeGreaterThanOrEqual(6);
  });
});
