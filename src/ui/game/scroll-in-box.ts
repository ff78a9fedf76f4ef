/**
 * Brings `element` into view inside the nearest box around it that scrolls (crossing shadow
 * roots), like `scrollIntoView({ block: 'nearest' })` but never further out: when no box
 * but the page itself scrolls (the lab's one-column layout on a phone or at 200 % zoom, where
 * the 3D view sits above the tasks), nothing moves, so the view stays where the learner is
 * looking. `scrollIntoView` would scroll every scrolling ancestor, the page included.
 */
export function scrollInBox(element: Element): void {
  const box = scrollBoxAround(element);
  if (!box) return;
  const inner = element.getBoundingClientRect();
  const outer = box.getBoundingClientRect();
  // "nearest": the least scroll that shows the element's top, and its bottom if both fit.
  if (inner.top < outer.top) box.scrollTop -= outer.top - inner.top;
  else if (inner.bottom > outer.bottom) box.scrollTop += Math.min(inner.bottom - outer.bottom, inner.top - outer.top);
}

/** Scrolls the nearest box around `element` that scrolls to its top; as scrollInBox, never the page itself. */
export function scrollBoxToTop(element: Element): void {
  const box = scrollBoxAround(element);
  if (box) box.scrollTop = 0;
}

function scrollBoxAround(element: Element): Element | null {
  for (let at = parentAcrossShadow(element); at; at = parentAcrossShadow(at)) {
    if (at === document.scrollingElement || at === document.body) return null;
    const { overflowY } = getComputedStyle(at);
    if (overflowY === 'auto' || overflowY === 'scroll') return at;
  }
  return null;
}

function parentAcrossShadow(element: Element): Element | null {
  if (element.parentElement) return element.parentElement;
  const root = element.getRootNode();
  return root instanceof ShadowRoot ? root.host : null;
}
