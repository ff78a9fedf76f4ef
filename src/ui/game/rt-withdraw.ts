import { msg, str } from '@lit/localize';
import { css, html } from 'lit';
import type { WithdrawReport } from '../../app/withdraw-data.ts';
import { askToConfirm, confirmDialog, confirmDialogStyles } from './confirm-dialog.ts';
import { fire, gameStyles } from './game-styles.ts';
import type { ProgressCommand } from './rt-progress-menu.ts';
import { LocalizedElement } from '../controls/localized-element.ts';

/**
 * @summary "Withdraw and delete my data" in the Menu: a confirmation that says what will be
 * deleted (and what cannot be: what was already handed in), then the `withdraw` command,
 * then what was deleted, with "Start again" (the page reloads and the assignment opens
 * afresh, asking for a code).
 * @fires progress-command - `{ kind: 'withdraw', done }`; `done` gets the report.
 */
export class RtWithdraw extends LocalizedElement {
  static override properties = { report: { state: true } };

  static override styles = [
    gameStyles,
    confirmDialogStyles,
    css`
      :host {
        display: grid;
      }
    `,
  ];

  /** What was deleted, once it was. */
  declare report: WithdrawReport | null;

  constructor() {
    super();
    this.report = null;
  }

  private withdraw(): void {
    fire<ProgressCommand>(this, 'progress-command', {
      kind: 'withdraw',
      done: (report) => {
        this.report = report;
        void this.updateComplete.then(() => this.renderRoot.querySelector<HTMLDialogElement>('dialog.report')?.showModal());
      },
    });
  }

  override render() {
    return html`
      <button class="danger" @click=${() => askToConfirm(this.renderRoot, 'withdraw')} title=${msg('Stop taking part and delete what this browser kept of this assignment (or of free play, when no assignment is open)')}>
        ${msg('Withdraw and delete my data…')}
      </button>
      ${confirmDialog({
        name: 'withdraw',
        title: msg('Withdraw and delete your data?'),
        body: html`<p>
            ${msg('This deletes from this browser: your progress with the record of what you did, your participant code, your survey and concept test answers and their backups. It cannot be undone.')}
          </p>
          <p>${msg('A results file or code you already handed in is not in this browser: ask your teacher to delete it. Close other tabs of this game first.')}</p>`,
        cancel: msg('Cancel'),
        confirm: msg('Delete my data'),
        confirmed: () => this.withdraw(),
      })}
      <dialog class="report" aria-labelledby="withdrawn-title" @close=${() => location.reload()}>
        <h3 id="withdrawn-title">${msg('Your data was deleted')}</h3>
        ${this.report ? reportText(this.report) : ''}
        <form method="dialog" class="actions">
          <button value="ok" class="primary" autofocus>${msg('Start again')}</button>
        </form>
      </dialog>
    `;
  }
}

function reportText(report: WithdrawReport) {
  const deleted = [
    report.progress ? msg('your progress and the record of what you did') : null,
    report.session ? msg('your participant code') : null,
    report.survey ? msg('your survey answers') : null,
    report.conceptTest ? msg('your concept test answers') : null,
    report.backups === 0 ? null : report.backups === 1 ? msg('1 backup') : msg(str`${report.backups} backups`),
  ].filter((item) => item !== null);
  return html`${deleted.length === 0 ? html`<p>${msg('There was nothing saved in this browser to delete.')}</p>` : html`<p>${msg('Deleted from this browser:')}</p><ul>${deleted.map((item) => html`<li>${item}</li>`)}</ul>`}
  ${report.failed.length === 0 ? '' : html`<p>⚠ ${msg("The browser refused to delete some of it: clear this site's data in the browser's settings.")}</p>`}`;
}

customElements.define('rt-withdraw', RtWithdraw);

declare global {
  interface HTMLElementTagNameMap {
    'rt-withdraw': RtWithdraw;
  }
}
