import { msg, str } from '@lit/localize';
import { css, html, nothing } from 'lit';
import { MAX_NUMBERED_CODES, numberedCodes } from '../../classroom/participant-code.ts';
import { classroomStyles } from './classroom-styles.ts';
import { LocalizedElement } from '../controls/localized-element.ts';

/**
 * @summary The printable handout of an assignment: a page with its title, QR code and link,
 * then (when the assignment asks for a participant code) numbered code slips to cut,
 * `5H2-01` … `5H2-30`, named after the class code (classroom/participant-code.ts). On screen
 * it is the number of slips and a Print button; the sheet itself shows only in print.
 */
export class RtTeacherHandout extends LocalizedElement {
  static override properties = {
    url: {},
    qr: {},
    heading: {},
    classCode: { attribute: false },
    askCodes: { type: Boolean },
    count: { state: true },
    status: { state: true },
  };

  static override styles = [
    classroomStyles,
    css`
      .row {
        display: flex;
        flex-wrap: wrap;
        gap: var(--rt-space);
        align-items: end;
      }
      label {
        display: grid;
        gap: 2px;
      }
      input[type='number'] {
        width: 6em;
        font: inherit;
        color: var(--rt-text);
        background: var(--rt-surface-2);
        border: 1px solid var(--rt-border);
        border-radius: 6px;
        padding: 6px 8px;
        min-height: var(--rt-target);
        box-sizing: border-box;
      }
      .sheet {
        display: none;
      }
      @media print {
        .controls {
          display: none;
        }
        .sheet {
          display: block;
          color: #000;
        }
        .first {
          text-align: center;
        }
        .first img {
          width: 11cm;
          height: 11cm;
        }
        .link {
          font-family: ui-monospace, monospace;
          font-size: 9pt;
          word-break: break-all;
        }
        .slips {
          break-before: page;
          display: grid;
          grid-template-columns: repeat(3, 1fr);
        }
        .slip {
          break-inside: avoid;
          border: 1px dashed #000;
          padding: 0.4cm;
          text-align: center;
        }
        .slip strong {
          display: block;
          font-size: 18pt;
          font-family: ui-monospace, monospace;
          letter-spacing: 0.05em;
        }
        .slip span {
          font-size: 8pt;
        }
      }
    `,
  ];

  declare url: string;
  declare qr: string;
  /** The assignment's title, at the top of the sheet and on each slip. */
  declare heading: string;
  /** The codes' prefix; without one they are P-01 …. */
  declare classCode: string | undefined;
  /** The assignment asks for a participant code: slips are printed. */
  declare askCodes: boolean;
  declare count: number;
  declare status: string;

  constructor() {
    super();
    this.url = '';
    this.qr = '';
    this.heading = '';
    this.classCode = undefined;
    this.askCodes = false;
    this.count = 30;
    this.status = '';
  }

  private get codes(): string[] {
    return this.askCodes ? numberedCodes(this.classCode ?? '', this.count) : [];
  }

  override render() {
    const codes = this.codes;
    return html`
      <div class="controls">
        <div class="row">
          ${
            this.askCodes
              ? html`<label>
                ${msg('Code slips')}
                <input
                  type="number"
                  name="slips"
                  min="1"
                  max=${MAX_NUMBERED_CODES}
                  .value=${String(this.count)}
                  @input=${(e: Event) => (this.count = Math.max(0, Math.min(MAX_NUMBERED_CODES, (e.target as HTMLInputElement).valueAsNumber || 0)))}
                />
              </label>`
              : nothing
          }
          <button type="button" ?disabled=${!this.url} @click=${() => print()}>${msg('Print a handout')}</button>
          ${codes.length > 0 ? html`<button type="button" @click=${this.copyCodes}>${msg('Copy the codes')}</button>` : nothing}
        </div>
        <p class="muted">
          ${
            codes.length > 0
              ? msg(str`A page with the QR code and the link, then ${codes.length} numbered code slips to cut: ${codes[0]} … ${codes[codes.length - 1]}.`)
              : msg('A page with the QR code and the link. With "Ask for a code" on, numbered code slips to cut follow.')
          }
          <span role="status">${this.status}</span>
        </p>
      </div>
      <div class="sheet">
        <div class="first">
          <h1>${this.heading}</h1>
          ${this.qr ? html`<img src=${this.qr} alt=${msg('QR code of the assignment link')} />` : nothing}
          <p>${msg('Scan the QR code with your phone or tablet, or type the link:')}</p>
          <p class="link">${this.url}</p>
          ${codes.length > 0 ? html`<p>${msg('When the game asks for your participant code, type the code on your slip.')}</p>` : nothing}
        </div>
        ${
          codes.length > 0
            ? html`<div class="slips">
              ${codes.map((code) => html`<div class="slip"><span>${msg('Your participant code')}</span><strong>${code}</strong><span>${this.heading}</span></div>`)}
            </div>`
            : nothing
        }
      </div>
    `;
  }

  /** The codes, one a line: for the dashboard's class list, or a spreadsheet of who has which. */
  private async copyCodes(): Promise<void> {
    try {
      await navigator.clipboard.writeText(this.codes.join('\n'));
      this.status = msg('Codes copied.');
    } catch {
      this.status = msg('The browser did not allow copying.');
    }
  }
}

customElements.define('rt-teacher-handout', RtTeacherHandout);

declare global {
  interface HTMLElementTagNameMap {
    'rt-teacher-handout': RtTeacherHandout;
  }
}
