import { msg, str } from '@lit/localize';
import { issueText } from '../../i18n/issue-text.ts';
import { html, nothing } from 'lit';
import { LocalizedElement } from '../controls/localized-element.ts';
import type { SceneParseResult } from '../../scene/scene-schema.ts';
import { decodeSceneLink } from '../../app/scene-link.ts';
import '../lab/rt-lab.ts';
import './rt-link-notice.ts';

/**
 * @summary The page of a shared scene link (#/s/…): the lab opened on the scene (rt-lab's
 * `sharedScene`: the free lab with every panel), or, when the link is damaged, the lab as
 * usual under a message that says why. Set `hash`.
 */
export class RtSceneLinkLab extends LocalizedElement {
  static override properties = { hash: {}, read: { state: true } };

  declare hash: string;
  /** The link as read, for `hash`; null while it is being read. */
  declare read: { hash: string; result: SceneParseResult } | null;

  constructor() {
    super();
    this.hash = '';
    this.read = null;
  }

  /** No shadow root, like the router: the lab stays reachable from the document. */
  protected override createRenderRoot(): HTMLElement {
    return this;
  }

  protected override willUpdate(): void {
    if (this.read?.hash !== this.hash) void this.decode(this.hash);
  }

  private async decode(hash: string): Promise<void> {
    const result = await decodeSceneLink(hash);
    if (hash === this.hash) this.read = { hash, result };
  }

  override render() {
    if (this.read?.hash !== this.hash) return nothing;
    const { result } = this.read;
    return result.ok
      ? html`<rt-lab .sharedScene=${result.scene}></rt-lab>`
      : html`<rt-link-notice .text=${msg(str`This scene link is damaged (${result.errors.map(issueText).join('; ')}). The lab opens without it.`)}></rt-link-notice><rt-lab></rt-lab>`;
  }
}

customElements.define('rt-scene-link-lab', RtSceneLinkLab);

declare global {
  interface HTMLElementTagNameMap {
    'rt-scene-link-lab': RtSceneLinkLab;
  }
}
