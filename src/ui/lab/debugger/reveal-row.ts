/**
 * Scrolls `list` (a scrolling box of the debugger) just enough to show `row`, and nothing
 * else: scrollIntoView would also scroll every box around it, so on a small screen, where the
 * debugger's parts scroll together in one column, a step would pull that column to the tree's
 * row and away from what the learner was reading.
 */
export function revealRow(list: Element, row: Element | null): void {
  if (!row) return;
  const box = list.getBoundingClientRect();
  const at = row.getBoundingClientRect();
  if (at.top < box.top) list.scrollTop -= box.top - at.top;
  else if (at.bottom > box.bottom) list.scrollTop += Math.min(at.bottom - box.bottom, at.top - box.top);
}
