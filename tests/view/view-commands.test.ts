import { describe, expect, it } from 'vitest';
import { gestureHelp, keyCommand, type KeyPress, keyHelp } from '../../src/view/view-commands.ts';

function press(key: string, modifiers: Partial<KeyPress> = {}): KeyPress {
  return { key, shiftKey: false, ctrlKey: false, altKey: false, metaKey: false, ...modifiers };
}

describe('the view’s keys', () => {
  it('orbit with arrows and pan with Shift+arrows, in the camera’s terms (right and up positive)', () => {
    expect(keyCommand(press('ArrowRight'), false)).toEqual({ kind: 'orbit', dxDeg: 5, dyDeg: 0 });
    expect(keyCommand(press('ArrowDown'), false)).toEqual({ kind: 'orbit', dxDeg: 0, dyDeg: -5 });
    expect(keyCommand(press('ArrowLeft', { shiftKey: true }), false)).toEqual({ kind: 'pan', dx: -0.05, dy: 0 });
    expect(keyCommand(press('ArrowUp', { shiftKey: true }), false)).toEqual({ kind: 'pan', dx: 0, dy: 0.05 });
  });

  it('zoom in with + (or =, unshifted on most keyboards) and out with −', () => {
    expect(keyCommand(press('+'), false)).toEqual({ kind: 'zoom', factor: 1.1 });
    expect(keyCommand(press('='), false)).toEqual({ kind: 'zoom', factor: 1.1 });
    expect(keyCommand(press('-'), false)).toEqual({ kind: 'zoom', factor: 1 / 1.1 });
  });

  it('switch gizmo modes with T, R, S in either case', () => {
    expect(keyCommand(press('t'), false)).toEqual({ kind: 'gizmo-mode', mode: 'translate' });
    expect(keyCommand(press('R', { shiftKey: true }), false)).toEqual({ kind: 'gizmo-mode', mode: 'rotate' });
    expect(keyCommand(press('s'), false)).toEqual({ kind: 'gizmo-mode', mode: 'scale' });
  });

  it('take Tab for local/world only while something is selected, so keyboard users can still leave the view', () => {
    expect(keyCommand(press('Tab'), true)).toEqual({ kind: 'toggle-space' });
    expect(keyCommand(press('Tab'), false)).toBeNull();
    expect(keyCommand(press('Tab', { shiftKey: true }), true)).toBeNull();
  });

  it('leave the browser’s and the app’s shortcuts alone (Ctrl+S saves, Alt+arrows go back)', () => {
    expect(keyCommand(press('s', { ctrlKey: true }), true)).toBeNull();
    expect(keyCommand(press('ArrowLeft', { altKey: true }), true)).toBeNull();
    expect(keyCommand(press('r', { metaKey: true }), true)).toBeNull();
    expect(keyCommand(press('x'), true)).toBeNull();
  });

  it('delete, escape, fly, select next/previous and help', () => {
    expect(keyCommand(press('Delete'), true)).toEqual({ kind: 'delete' });
    expect(keyCommand(press('Backspace'), true)).toEqual({ kind: 'delete' });
    expect(keyCommand(press('Escape'), true)).toEqual({ kind: 'escape' });
    expect(keyCommand(press('f'), false)).toEqual({ kind: 'fly' });
    expect(keyCommand(press('p'), false)).toEqual({ kind: 'show-pixel-rays' });
    expect(keyCommand(press('n'), false)).toEqual({ kind: 'select-next', step: 1 });
    expect(keyCommand(press('N', { shiftKey: true }), false)).toEqual({ kind: 'select-next', step: -1 });
    expect(keyCommand(press('?', { shiftKey: true }), false)).toEqual({ kind: 'help' });
    expect(keyCommand(press('g'), false)).toEqual({ kind: 'toggle-snap' });
  });

  it('are all in the help panel, and every single key the help names does something', () => {
    const printed = keyHelp().flatMap((row) => row.keys);
    const asKey: Record<string, string> = { '←': 'ArrowLeft', '→': 'ArrowRight', '↑': 'ArrowUp', '↓': 'ArrowDown', '−': '-', Esc: 'Escape' };
    for (const label of printed.filter((key) => !key.includes('+ ') && key !== 'Shift')) {
      expect(keyCommand(press(asKey[label] ?? label), true), label).not.toBeNull();
    }
    // Every command a key gives appears in the help (by its key).
    for (const key of ['ArrowUp', '+', '-', 't', 'r', 's', 'g', 'Tab', 'n', 'Delete', 'Escape', 'f', 'p', '?']) {
      const shown = key.length === 1 ? key.toUpperCase() : { ArrowUp: '↑', Delete: 'Delete', Escape: 'Esc', Tab: 'Tab' }[key];
      expect(printed.some((label) => label === shown || (key === '-' && label === '−')), key).toBe(true);
    }
    expect(gestureHelp().length).toBeGreaterThanOrEqual(6);
  });
});
