import type { RtToast } from '../controls/rt-toast.ts';

/** A box on screen, in CSS px from the viewport's top (a DOMRect is one). */
interface Span {
  top: number;
  height: number;
}

/** Where a message goes: an end of the task column, or the foot of the panels column (lab-layout.css.ts places each). */
export type ToastPlace = 'top' | 'bottom' | 'panels';

/**
 * Which end of the task column a message goes to first (rt-toast.ts): the end away from the
 * current task, so that it covers neither the task's text nor its Hint button. A new current
 * task scrolls into view at the column's foot (a message in the bottom corner covered it, at
 * 1366×768 and at 200 % zoom alike), a long one or a level's first at its top. Without a
 * current task (the free lab, the map): the bottom, its old place.
 */
export function toastPlace(currentTask: Span | null, viewportHeight: number): 'top' | 'bottom' {
  if (!currentTask) return 'bottom';
  return currentTask.top + currentTask.height / 2 > viewportHeight / 2 ? 'top' : 'bottom';
}

function overlaps(a: Span, b: Span): boolean {
  return a.top < b.top + b.height && b.top < a.top + a.height;
}

/**
 * The place for a message of its height: the first end of the task column (the one
 * toastPlace prefers, then the other) where its box (`boxAt`, measured there) covers none of
 * `kept`: the level's title and intro and the current task. A level opens at its title with
 * its first task under the intro; the end away from that task was the top, over the intro
 * the learner reads first. When each end covers one of them (a long intro, a tall task), the
 * message goes over the foot of the panels column, as in the free lab, if that column is
 * on screen beside the view; if not (a phone's layout), to the preferred end.
 */
export function clearToastPlace(kept: Span[], preferred: 'top' | 'bottom', boxAt: (place: 'top' | 'bottom') => Span, panelsShown: boolean): ToastPlace {
  const ends = preferred === 'top' ? (['top', 'bottom'] as const) : (['bottom', 'top'] as const);
  const clear = ends.find((end) => {
    const box = boxAt(end);
    return kept.every((span) => span.height === 0 || !overlaps(box, span));
  });
  return clear ?? (panelsShown ? 'panels' : preferred);
}

/** Shows a message in the lab's message element (`labRoot`: rt-lab's shadow root), placed once it is drawn, before the frame is painted. */
export function showToast(labRoot: ParentNode, text: string, tone: 'info' | 'error'): void {
  const toast = labRoot.querySelector<RtToast>('rt-toast');
  if (!toast) return;
  toast.show(text, tone);
  void toast.updateComplete.then(() => placeToast(labRoot, toast));
}

/** Places the message element by its height: it is put at each end in turn and measured there (the layout's media queries decide where an end is). */
function placeToast(labRoot: ParentNode, toast: RtToast): void {
  const questRoot = labRoot.querySelector('rt-quest-panel')?.shadowRoot;
  const current = questRoot?.querySelector('rt-task-card[status="current"]')?.getBoundingClientRect() ?? null;
  const intro = questRoot?.querySelector('header')?.getBoundingClientRect();
  const panels = labRoot.querySelector('.sidebar')?.getBoundingClientRect();
  const boxAt = (place: 'top' | 'bottom') => {
    toast.dataset.place = place;
    return toast.getBoundingClientRect();
  };
  const kept = [intro, current].filter((span): span is DOMRect => span !== undefined && span !== null);
  toast.dataset.place = clearToastPlace(kept, toastPlace(current, window.innerHeight), boxAt, (panels?.width ?? 0) > 0);
}
