import { msg } from '@lit/localize';
import { css, html, nothing } from 'lit';
import { LocalizedElement } from '../controls/localized-element.ts';
import type { DamagedSave } from '../../app/damaged-saves.ts';
import type { WithdrawReport } from '../../app/withdraw-data.ts';
import type { Locale } from '../../quest/localized-text.ts';
import { damagedSavesList, damagedSavesStyles } from './damaged-saves-list.ts';
import { askToConfirm, confirmDialog, confirmDialogStyles } from './confirm-dialog.ts';
import { fire, gameStyles } from './game-styles.ts';

/** The detail of `progress-command`. */
export type ProgressCommand =
  | { kind: 'locale'; locale: Locale }
  | { kind: 'palette'; colorBlind: boolean }
  | { kind: 'export' }
  | { kind: 'import'; text: string; fileName: string }
  | { kind: 'reset' }
  | { kind: 'withdraw'; done: (report: WithdrawReport) => void }
  | { kind: 'damaged-download' | 'damaged-restore' | 'damaged-delete'; key: string };

/**
 * @summary The header's menu: the language, the rays' colours (saved with the progress, for
 * every level), and the learner's progress:
 * export as a file, import a file, reset (after a confirmation dialog); why progress is not
 * being saved, while it is not (`saveProblem`); the damaged saves, to download, restore
 * or delete (`damagedSaves`); last, whether the app works offline in this browser.
 *
 * @fires progress-command - CustomEvent<ProgressCommand>.
 */
export class RtProgressMenu extends LocalizedElement {
  static override properties = {
    locale: {},
    colorBlind: { type: Boolean, attribute: 'color-blind' },
    saveProblem: { attribute: false },
    damagedSaves: { attribute: false },
  };
  static override styles = [
    gameStyles,
    damagedSavesStyles,
    confirmDialogStyles,
    css`
      [popover] {
        width: 280px;
        max-height: 85vh;
        overflow-y: auto;
      }
      fieldset {
        margin: 0 0 12px;
        padding: 0;
        border: 0;
      }
      legend {
        font-weight: 600;
        margin-bottom: 4px;
      }
      label {
        display: flex;
        align-items: center;
        gap: 8px;
        min-height: var(--rt-target);
      }
      .stack {
        display: grid;
        gap: 8px;
      }
      input[type='file'] {
        display: none;
      }
    `,
  ];

  declare locale: Locale;
  /** Whether the rays are drawn in the colour-blind-safe palette. */
  declare colorBlind: boolean;
  /** Why progress is not being saved now (with what to do), or ''. */
  declare saveProblem: string;
  declare damagedSaves: readonly DamagedSave[];

  constructor() {
    super();
    this.locale = 'en';
    this.colorBlind = false;
    this.saveProblem = '';
    this.damagedSaves = [];
  }

  override render() {
    const send = (command: ProgressCommand) => fire(this, 'progress-command', command);
    return html`
      <button popovertarget="menu" title=${msg('Language, ray colours and progress: export, import, reset')}>☰ ${msg('Menu')}</button>
      <div id="menu" popover>
        ${choices(
          msg('Language'),
          'locale',
          [
            ['en', 'English'],
            ['nl', 'Nederlands'],
          ] as const,
          this.locale,
          (locale) => send({ kind: 'locale', locale }),
        )}
        ${choices(
          msg('Ray colours'),
          'palette',
          [
            [false, msg('Standard')],
            [true, msg('Colour-blind safe')],
          ] as const,
          this.colorBlind,
          (colorBlind) => send({ kind: 'palette', colorBlind }),
        )}
        <fieldset class="stack">
          <legend>${msg('Your progress')}</legend>
          ${this.saveProblem ? html`<p class="save-problem" role="status">⚠ ${this.saveProblem}</p>` : nothing}
          <button @click=${() => send({ kind: 'export' })} title=${msg('Download your progress as a file, to keep it or take it to another computer')}>${msg('Export progress…')}</button>
          <button @click=${() => this.renderRoot.querySelector<HTMLInputElement>('input[type=file]')?.click()} title=${msg('Continue from a progress file you exported')}>
            ${msg('Import progress…')}
          </button>
          <input type="file" accept=".json,application/json" aria-label=${msg('Progress file to import')} @change=${this.imported} />
          <button class="danger" @click=${() => askToConfirm(this.renderRoot, 'reset')} title=${msg('Start the game from the beginning')}>${msg('Reset progress…')}</button>
          <rt-withdraw></rt-withdraw>
        </fieldset>
        ${damagedSavesList(this.damagedSaves, send)}
        <rt-offline-status></rt-offline-status>
      </div>
      ${confirmDialog({
        name: 'reset',
        title: msg('Reset all progress?'),
        body: html`<p>${msg('Your points, badges and finished levels will be gone. Export your progress first if you may want it back.')}</p>`,
        cancel: msg('Cancel'),
        confirm: msg('Reset'),
        // Sent once the dialog has closed, so that its message is not under the dialog.
        confirmed: () => send({ kind: 'reset' }),
      })}
    `;
  }

  private async imported(event: Event): Promise<void> {
    const input = event.target as HTMLInputElement;
    const file = input.files?.[0];
    input.value = '';
    if (!file) return;
    fire<ProgressCommand>(this, 'progress-command', { kind: 'import', text: await file.text(), fileName: file.name });
  }
}

/** A group of radio buttons: one of `options` (value, name), `current` checked. */
function choices<T>(legend: string, name: string, options: readonly (readonly [T, string])[], current: T, choose: (value: T) => void) {
  return html`<fieldset>
    <legend>${legend}</legend>
    ${options.map(
      ([value, label]) => html`<label>
        <input type="radio" name=${name} .checked=${current === value} @change=${() => choose(value)} /> ${label}
      </label>`,
    )}
  </fieldset>`;
}

customElements.define('rt-progress-menu', RtProgressMenu);

declare global {
  interface HTMLElementTagNameMap {
    'rt-progress-menu': RtProgressMenu;
  }
}
