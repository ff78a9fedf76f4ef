import { html, LitElement } from 'lit';
import './rt-lab.ts';

/**
 * @summary The app's top level: picks the page from the address's #fragment. The lab (with
 * the game) is the default; the classroom adds the teacher page, the dashboard and
 * assignment links here.
 */
export class RtApp extends LitElement {
  static override properties = { route: { state: true } };

  declare route: string;
  private readonly onHashChange = () => (this.route = location.hash);

  constructor() {
    super();
    this.route = location.hash;
  }

  override connectedCallback(): void {
    super.connectedCallback();
    addEventListener('hashchange', this.onHashChange);
  }

  override disconnectedCallback(): void {
    super.disconnectedCallback();
    removeEventListener('hashchange', this.onHashChange);
  }

  /** No shadow root: a router has no looks of its own, and pages stay reachable from the document. */
  protected override createRenderRoot(): HTMLElement {
    return this;
  }

  override render() {
    return html`<rt-lab></rt-lab>`;
  }
}

customElements.define('rt-app', RtApp);

declare global {
  interface HTMLElementTagNameMap {
    'rt-app': RtApp;
  }
}
