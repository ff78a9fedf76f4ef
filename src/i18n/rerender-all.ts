/**
 * Asks every Lit element under `root`, in the page and inside every shadow root, to render
 * again. After a language change each element's render calls msg() anew, so the whole page
 * switches at once; this is what @lit/localize's @localized() does per class, done once for
 * the page so that no element needs its own listener.
 */
export function rerenderAll(root: ParentNode): void {
  for (const element of root.querySelectorAll('*')) {
    if (typeof (element as { requestUpdate?: unknown }).requestUpdate === 'function') (element as unknown as { requestUpdate(): void }).requestUpdate();
    if (element.shadowRoot) rerenderAll(element.shadowRoot);
  }
}
