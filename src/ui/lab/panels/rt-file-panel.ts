import { msg, str } from '@lit/localize';
import { css, html, type CSSResultGroup } from 'lit';
import { ifDefined } from 'lit/directives/if-defined.js';
import { readSceneFile, sceneFileName, sceneFileText } from '../../../app/scene-file.ts';
import { LONG_LINK_CHARACTERS, sceneLinkUrl } from '../../../app/scene-link.ts';
import { downloadText } from '../../../util/download-file.ts';
import { messageLine } from '../../controls/status-message.ts';
import { StorePanel } from './store-panel.ts';
import { shownName } from '../scene-names.ts';
import { currentLocale } from '../../../i18n/locale.ts';
import { issueText } from '../../../i18n/issue-text.ts';

/** A note under the buttons: what happened, or why a file could not be loaded. */
interface Note {
  text: string;
  problem: boolean;
}

/**
 * @summary Save, load and share the scene (the sandbox level): "Save as file" downloads
 * `<scene-name>.scene.json`; "Load file" reads one (a level file too) and replaces the
 * scene, or says what is wrong with it and keeps the scene; "Share link" makes a link that
 * opens the scene (#/s/…), copies it and shows it to copy by hand where the clipboard is
 * not allowed. Nothing leaves the computer but what the learner copies.
 *
 * Dispatches `scene.saved` ({ to: 'file' | 'link' }) and, for a loaded file, `scene.loaded`.
 */
export class RtFilePanel extends StorePanel<'file'> {
  protected readonly controlPanel = 'file';
  static override properties = { ...StorePanel.properties, link: { state: true }, note: { state: true } };

  static override styles: CSSResultGroup = [
    StorePanel.styles,
    css`
      .buttons {
        display: flex;
        flex-wrap: wrap;
        gap: 8px;
      }
      input[type='file'] {
        display: none;
      }
      label.link {
        display: grid;
        gap: 4px;
        margin-top: 8px;
      }
      label.link input {
        width: 100%;
      }
      .message {
        white-space: pre-line;
      }
    `,
  ];

  /** The last link made, shown to copy by hand. */
  declare link: string;
  declare note: Note | null;

  constructor() {
    super();
    this.link = '';
    this.note = null;
  }

  private saveFile(): void {
    const scene = this.state?.scene;
    if (!scene) return;
    downloadText(sceneFileText(scene), sceneFileName(scene, currentLocale()), 'application/json');
    this.note = { text: msg(str`Saved as ${sceneFileName(scene, currentLocale())} in your downloads.`), problem: false };
    this.store?.dispatch({ type: 'scene.saved', to: 'file' });
  }

  private async loadFile(event: Event): Promise<void> {
    const input = event.target as HTMLInputElement;
    const file = input.files?.[0];
    input.value = '';
    if (!file) return;
    const read = readSceneFile(await file.text(), file.size);
    if (!read.ok) {
      this.note = {
        text: msg(str`${file.name} is not a scene file this app can open; your scene is unchanged.\n${read.errors.map(issueText).join('\n')}`),
        problem: true,
      };
      return;
    }
    const error = this.store?.dispatch({ type: 'scene.loaded', scene: read.scene });
    this.note = error
      ? { text: msg(str`${file.name} could not be loaded; your scene is unchanged.\n${error}`), problem: true }
      : { text: msg(str`Loaded ${shownName(read.scene.name, file.name)}.`), problem: false };
  }

  private async shareLink(): Promise<void> {
    const scene = this.state?.scene;
    if (!scene) return;
    this.link = await sceneLinkUrl(scene, location.href);
    const long =
      this.link.length > LONG_LINK_CHARACTERS
        ? ` ${msg(str`The link is long (${this.link.length} characters); some chat programs cut long links, so a file is safer.`)}`
        : '';
    try {
      await navigator.clipboard.writeText(this.link);
      this.note = { text: msg('The link is copied: paste it to share this scene.') + long, problem: false };
    } catch {
      // No clipboard (a page not served over https, or permission refused): the field below is selected to copy by hand.
      this.note = { text: msg('Copy the link below (Ctrl+C or long-press) to share this scene.') + long, problem: false };
      await this.updateComplete;
      this.renderRoot.querySelector<HTMLInputElement>('label.link input')?.select();
    }
    this.store?.dispatch({ type: 'scene.saved', to: 'link' });
  }

  override render() {
    return html`<rt-panel-section heading=${msg('Save and share')} name="file">
      <div class="buttons">
        <button name="save" data-guide=${ifDefined(this.guideOf('save'))} @click=${this.saveFile} title=${msg('Download this scene as a .scene.json file')}>${msg('Save as file')}</button>
        <button
          name="load"
          data-guide=${ifDefined(this.guideOf('load'))}
          @click=${() => this.renderRoot.querySelector<HTMLInputElement>('input[type=file]')?.click()}
          title=${msg('Open a .scene.json file; if it cannot be read, your scene stays as it is')}
        >
          ${msg('Load file…')}
        </button>
        <input type="file" accept=".json,application/json" @change=${this.loadFile} aria-label=${msg('Scene file to load')} />
        <button name="share" data-guide=${ifDefined(this.guideOf('share'))} @click=${this.shareLink} title=${msg('Make a link that opens this scene, and copy it')}>${msg('Share link')}</button>
      </div>
      ${
        this.link
          ? html`<label class="link">
            ${msg('Link to this scene')}
            <input type="text" readonly .value=${this.link} @focus=${(event: FocusEvent) => (event.target as HTMLInputElement).select()} />
          </label>`
          : null
      }
      ${messageLine(this.note?.text, this.note?.problem ?? false)}
    </rt-panel-section>`;
  }
}

customElements.define('rt-file-panel', RtFilePanel);

declare global {
  interface HTMLElementTagNameMap {
    'rt-file-panel': RtFilePanel;
  }
}
