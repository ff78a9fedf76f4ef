import type { RtToast } from '../controls/rt-toast.ts';

/** A box on screen, in CSS px from the viewport's top (a DOMRect is one). */
interface Span {
  top: number;
  height: number;
}

/**
 * Which end of the task column a message goes to (rt-toast.ts; lab-layout.css.ts places
 * it): the end away from the current task, so that it covers neither the task's text nor its
 * Hint button. A new current task scrolls into view at the column's foot (a message in the
 * bottom corner covered it, at 1366×768 and at 200 % zoom alike), a long one or a level's
 * first at its top. Without a current task (the free lab, the map): the bottom, its old place.
 */
export function toastPlace(currentTask: Span | null, viewportHeight: number): 'top' | 'bottom' {
  if (!currentTask) return 'bottom';
  return currentTask.top + currentTask.height / 2 > viewportHeight / 2 ? 'top' : 'bottom';
}

/** The lab's message element, placed for a new message by where the current task is (`labRoot`: rt-lab's shadow root). */
export function placedToast(labRoot: ParentNode): RtToast | null {
  const toast = labRoot.querySelector<RtToast>('rt-toast');
  const current = labRoot.querySelector('rt-quest-panel')?.shadowRoot?.querySelector('rt-task-card[status="current"]');
  if (toast) toast.dataset.place = toastPlace(current?.getBoundingClientRect() ?? null, window.innerHeight);
  return toast;
}
