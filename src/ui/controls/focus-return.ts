/**
 * Where the keyboard focus was when a window opened over the page (the render window, the
 * level map), to put it back when the window closes (WCAG 2.4.3, focus order): without it,
 * closing with Esc leaves the focus on the page's body and a keyboard user starts again
 * from the top. Native <dialog>s opened with showModal() and popovers do this themselves.
 */
export class FocusReturn {
  private opener: HTMLElement | null = null;

  /** Call as the window opens, before it takes the focus. */
  remember(): void {
    const active = deepActiveElement();
    this.opener = active && active !== document.body ? active : null;
  }

  /**
   * Call once the window has closed: back to the opener, unless the learner has already
   * put the focus somewhere else on purpose (it is neither lost nor still in `window`).
   */
  restore(window: Element): void {
    const opener = this.opener;
    this.opener = null;
    if (!opener?.isConnected) return;
    const now = deepActiveElement();
    if (now && now !== document.body && !isInside(now, window)) return;
    opener.focus();
  }
}

/** The focused element, looking through shadow roots (document.activeElement stops at the first host). */
function deepActiveElement(): HTMLElement | null {
  let active = document.activeElement;
  while (active?.shadowRoot?.activeElement) active = active.shadowRoot.activeElement;
  return active instanceof HTMLElement ? active : null;
}

/** Whether `node` is `container` or inside it, across shadow roots. */
function isInside(node: Node, container: Element): boolean {
  for (let at: Node | null = node; at; at = at.parentNode ?? (at instanceof ShadowRoot ? at.host : null)) {
    if (at === container) return true;
  }
  return false;
}
