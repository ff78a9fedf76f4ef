import { localNumbers } from '../i18n/number-format.ts';
import type { GizmoMode } from './gizmo-modes.ts';

// The keyboard's gizmo steps, apart from their three.js maths (gizmo-nudge.ts): the view's
// key list and help text need them in the first load, before three.js has arrived.

/** The arrow keys (and Page Up / Page Down for the third direction) as directions on screen. */
export type NudgeDirection = 'left' | 'right' | 'up' | 'down' | 'farther' | 'nearer';

/** One key press: a small step, or with Shift a big one (the big ones are the snapping steps). */
export const NUDGE_STEPS = {
  /** metres */
  translate: { small: 0.1, big: 0.5 },
  /** degrees */
  rotate: { small: 5, big: 15 },
  /** the scale is multiplied (up, right) or divided (down, left) by this */
  scale: { small: 1.1, big: 1.5 },
} as const;

const numbers = localNumbers({ maximumFractionDigits: 2 });

/** One step of the keys in a gizmo mode, as the learner reads it: "0.1 m", "5°", "×1.1". */
export function nudgeStepText(mode: GizmoMode, big: boolean): string {
  const step = NUDGE_STEPS[mode][big ? 'big' : 'small'];
  if (mode === 'translate') return `${numbers.format(step)} m`;
  if (mode === 'rotate') return `${numbers.format(step)}°`;
  return `×${numbers.format(step)}`;
}
