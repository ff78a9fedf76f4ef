import { msg, str } from '@lit/localize';
import type { GizmoMode } from './gizmo-modes.ts';
import { type NudgeDirection, nudgeStepText } from './nudge-steps.ts';

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
  | { kind: 'nudge'; direction: NudgeDirection; big: boolean }
  | { kind: 'toggle-pixel' }
  | { kind: 'pixel-step'; dx: number; dy: number }
  | { kind: 'help' };

/**
 * What the arrow keys act on in the focused view: the viewpoint (orbit, Shift pans), the
 * selection (a step in the gizmo's mode, Shift a big one: while its handles are shown), or
 * the chosen pixel of the camera's screen (the next pixel; Shift still pans).
 */
export type ArrowTarget = 'view' | 'selection' | 'pixel';

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

const ARROWS: Readonly<Record<string, NudgeDirection>> = {
  ArrowLeft: 'left',
  ArrowRight: 'right',
  ArrowUp: 'up',
  ArrowDown: 'down',
  PageUp: 'farther',
  PageDown: 'nearer',
};

/** The arrows as (dx, dy) on the screen, y down as pixel rows count. */
const PIXEL_STEPS: Readonly<Record<string, [number, number]>> = { ArrowLeft: [-1, 0], ArrowRight: [1, 0], ArrowUp: [0, -1], ArrowDown: [0, 1] };

/**
 * The command for a key press in the focused view, or null for keys the view leaves alone:
 * Tab always (the view is no focus trap: WCAG 2.1.2), Ctrl+S, Alt+←. `arrows` says what
 * the arrow keys act on (see ArrowTarget).
 */
export function keyCommand(press: KeyPress, arrows: ArrowTarget): ViewCommand | null {
  if (press.ctrlKey || press.metaKey || press.altKey) return null;
  const direction = ARROWS[press.key];
  if (direction && arrows === 'selection') return { kind: 'nudge', direction, big: press.shiftKey };
  const pixelStep = PIXEL_STEPS[press.key];
  if (pixelStep && arrows === 'pixel' && !press.shiftKey) return { kind: 'pixel-step', dx: pixelStep[0], dy: pixelStep[1] };
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
    case 'z':
      return { kind: 'show-pixel-rays' };
    case 'n':
      return { kind: 'select-next', step: press.shiftKey ? -1 : 1 };
    case 'l':
      return { kind: 'toggle-space' };
    case 'p':
      return { kind: 'toggle-pixel' };
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
    { keys: ['←', '→', '↑', '↓'], description: msg('Orbit around the point you look at (while nothing is selected)') },
    { keys: ['Shift + ←/→/↑/↓'], description: msg('Pan: slide the view sideways, up or down') },
    { keys: ['←', '→', '↑', '↓', 'Page Up', 'Page Down'], description: nudgeHelp() },
    { keys: ['P'], description: msg("Choose a pixel of the camera's screen (the arrows then go to the next pixel); P again shows every pixel's rays") },
    { keys: ['+', '−'], description: msg('Zoom in and out') },
    { keys: ['T'], description: msg('Gizmo: move the selection') },
    { keys: ['R'], description: msg('Gizmo: rotate the selection') },
    { keys: ['S'], description: msg('Gizmo: scale the selection') },
    { keys: ['L'], description: msg('Switch the gizmo between local and world axes') },
    { keys: ['Shift'], description: msg('Hold while dragging the gizmo to snap: 0.25 m, 15°, 0.25×') },
    { keys: ['G'], description: msg('Snapping on or off without holding Shift') },
    { keys: ['N', 'Shift + N'], description: msg('Select the next or previous object, light or camera') },
    { keys: ['Delete'], description: msg('Delete the selected object or light') },
    { keys: ['Esc'], description: msg("Deselect; show every pixel's rays again; leave the camera view; close this panel") },
    { keys: ['Tab'], description: msg('Leave the 3D view for the next control (always)') },
    { keys: ['F'], description: msg("Fly to the ray tracer's camera, and back") },
    { keys: ['Z'], description: msg("Show the chosen pixel's rays: the view moves so that its whole ray path fits") },
    { keys: ['?'], description: msg('Open this help') },
  ];
}

function nudgeHelp(): string {
  const [move, turn, grow] = (['translate', 'rotate', 'scale'] as const).map((mode) => nudgeStepText(mode, false));
  const [bigMove, bigTurn, bigGrow] = (['translate', 'rotate', 'scale'] as const).map((mode) => nudgeStepText(mode, true));
  return msg(
    str`With something selected (and its gizmo shown): move, turn or scale it one step in the gizmo's mode (${move}, ${turn}, ${grow}); with Shift a big step (${bigMove}, ${bigTurn}, ${bigGrow}). Page Up and Page Down move it away or nearer.`,
  );
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
