import { msg } from '@lit/localize';
import type { GizmoMode } from './gizmo-modes.ts';

/**
 * Everything the user can ask of the 3D view, whether by key, by toolbar button or by the
 * help panel: one vocabulary, so a key and its button can never drift apart.
 * Orbit and pan are in the camera's terms: +dx moves the viewpoint right, +dy up.
 */
export type ViewCommand =
  | { kind: 'orbit'; dxDeg: number; dyDeg: number }
  | { kind: 'pan'; dx: number; dy: number }
  | { kind: 'zoom'; factor: number }
  | { kind: 'gizmo-mode'; mode: GizmoMode }
  | { kind: 'toggle-space' }
  | { kind: 'toggle-snap' }
  | { kind: 'delete' }
  | { kind: 'escape' }
  | { kind: 'fly' }
  | { kind: 'show-pixel-rays' }
  | { kind: 'select-next'; step: 1 | -1 }
  | { kind: 'help' };

/** The parts of a KeyboardEvent a command depends on (a plain object in tests). */
export interface KeyPress {
  key: string;
  shiftKey: boolean;
  ctrlKey: boolean;
  altKey: boolean;
  metaKey: boolean;
}

/** One arrow press orbits this far; held down, key repeat turns it into a smooth turn. */
export const KEY_ORBIT_DEG = 5;
/** One arrow press with Shift pans by this share of the view's height. */
export const KEY_PAN = 0.05;
export const KEY_ZOOM = 1.1;

/**
 * The command for a key press in the focused view, or null for keys the view leaves alone
 * (so Tab still moves focus when nothing is selected, and Ctrl+S still saves).
 * `hasSelection` decides Tab: with a selection it switches local/world axes, as in the
 * Virtual Ray Tracer; without one it stays the browser's focus key.
 */
export function keyCommand(press: KeyPress, hasSelection: boolean): ViewCommand | null {
  if (press.ctrlKey || press.metaKey || press.altKey) return null;
  const step = press.shiftKey ? KEY_PAN : KEY_ORBIT_DEG;
  const move = (dx: number, dy: number): ViewCommand =>
    press.shiftKey ? { kind: 'pan', dx: dx * step, dy: dy * step } : { kind: 'orbit', dxDeg: dx * step, dyDeg: dy * step };
  switch (press.key) {
    case 'ArrowLeft':
      return move(-1, 0);
    case 'ArrowRight':
      return move(1, 0);
    case 'ArrowUp':
      return move(0, 1);
    case 'ArrowDown':
      return move(0, -1);
    case '+':
    case '=':
      return { kind: 'zoom', factor: KEY_ZOOM };
    case '-':
    case '_':
      return { kind: 'zoom', factor: 1 / KEY_ZOOM };
    case 'Tab':
      return hasSelection && !press.shiftKey ? { kind: 'toggle-space' } : null;
    case 'Delete':
    case 'Backspace':
      return { kind: 'delete' };
    case 'Escape':
      return { kind: 'escape' };
    case '?':
      return { kind: 'help' };
  }
  switch (press.key.toLowerCase()) {
    case 't':
      return { kind: 'gizmo-mode', mode: 'translate' };
    case 'r':
      return { kind: 'gizmo-mode', mode: 'rotate' };
    case 's':
      return { kind: 'gizmo-mode', mode: 'scale' };
    case 'g':
      return { kind: 'toggle-snap' };
    case 'f':
      return { kind: 'fly' };
    case 'p':
      return { kind: 'show-pixel-rays' };
    case 'n':
      return { kind: 'select-next', step: press.shiftKey ? -1 : 1 };
  }
  return null;
}

/** A row of the help panel: the keys (as printed on the keyboard) and what they do. */
export interface KeyHelp {
  keys: string[];
  description: string;
}

/** Every key of the view, for the help panel (built on demand so msg() sees the current locale). */
export function keyHelp(): KeyHelp[] {
  return [
    { keys: ['←', '→', '↑', '↓'], description: msg('Orbit around the point you look at') },
    { keys: ['Shift + ←/→/↑/↓'], description: msg('Pan: slide the view sideways, up or down') },
    { keys: ['+', '−'], description: msg('Zoom in and out') },
    { keys: ['T'], description: msg('Gizmo: move the selection') },
    { keys: ['R'], description: msg('Gizmo: rotate the selection') },
    { keys: ['S'], description: msg('Gizmo: scale the selection') },
    { keys: ['Tab'], description: msg('Switch the gizmo between local and world axes (while something is selected)') },
    { keys: ['Shift'], description: msg('Hold while dragging the gizmo to snap: 0.25 m, 15°, 0.25×') },
    { keys: ['G'], description: msg('Snapping on or off without holding Shift') },
    { keys: ['N', 'Shift + N'], description: msg('Select the next or previous object, light or camera') },
    { keys: ['Delete'], description: msg('Delete the selected object or light') },
    { keys: ['Esc'], description: msg('Deselect; leave the camera view; close this panel') },
    { keys: ['F'], description: msg("Fly to the ray tracer's camera, and back") },
    { keys: ['P'], description: msg("Show the chosen pixel's rays: the view moves so that its whole ray path fits") },
    { keys: ['?'], description: msg('Open this help') },
  ];
}

/** Every pointer and touch gesture of the view, for the help panel. */
export function gestureHelp(): KeyHelp[] {
  return [
    { keys: [msg('Left drag'), msg('One finger')], description: msg('Orbit around the point you look at') },
    { keys: [msg('Right drag'), msg('Two fingers')], description: msg('Pan: slide the view') },
    { keys: [msg('Scroll wheel'), msg('Pinch')], description: msg('Zoom in and out') },
    { keys: [msg('Click'), msg('Tap')], description: msg('Select an object, a light or the camera; on empty space: deselect') },
    { keys: [msg('Click a screen pixel')], description: msg('Show only the rays of that pixel; click it again to show all') },
    { keys: [msg('Drag a gizmo handle')], description: msg('Move, rotate or scale the selection along that axis') },
    { keys: [msg('Point at a ray')], description: msg('See its type, contribution and colour') },
  ];
}
