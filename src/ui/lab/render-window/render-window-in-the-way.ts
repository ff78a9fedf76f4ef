import type { LabState } from '../../../lab-state/lab-state.ts';

/** What the lab saw of the game the last time it asked, and sees now. */
export interface GuideAndLook {
  /** What the hint ring points at, or null. */
  ring: string | null;
  /** The last declared view's way of looking (a new object for every view applied). */
  look: LabState['look'];
}

/**
 * Whether the open render window must close because the game now needs the 3D view it
 * covers: a task's declared view that frames something in 3D or looks through the camera,
 * or a new hint ring on something the window covers (`ringCovered` says whether it does:
 * a ring on a panel beside the window leaves it open, so an image the learner is looking at
 * stays on show while the next task asks for a slider). A task that moves nothing leaves
 * the window open; so does a ring on the window's own controls.
 */
export function renderWindowInTheWay(before: GuideAndLook, now: GuideAndLook, ringCovered: (ring: string) => boolean): boolean {
  const newLook = now.look !== before.look && (now.look?.frame !== undefined || now.look?.throughCamera === true);
  const newRing = now.ring !== before.ring && now.ring !== null && !now.ring.startsWith('render.') && ringCovered(now.ring);
  return newLook || newRing;
}

/** A box's edges on the screen, as getBoundingClientRect gives them. */
type Edges = Pick<DOMRectReadOnly, 'left' | 'top' | 'right' | 'bottom'>;

/** Whether two boxes on the screen overlap (touching edges do not). */
export function boxesOverlap(a: Edges, b: Edges): boolean {
  return a.left < b.right && b.left < a.right && a.top < b.bottom && b.top < a.bottom;
}
