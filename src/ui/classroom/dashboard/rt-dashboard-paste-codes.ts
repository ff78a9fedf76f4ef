import { msg, str } from '@lit/localize';
import { css, html } from 'lit';
import type { DroppedFile } from '../../../classroom/dashboard-class.ts';
import type { SkippedFile } from '../../../classroom/dashboard-record.ts';
import { decodeResultsCode, findResultsCodes, RESULTS_CODE_PREFIX } from '../../../classroom/results-code.ts';
import { classroomStyles } from '../classroom-styles.ts';
import { codeBoxStyles } from '../code-box.css.ts';
import { LocalizedElement } from '../../controls/localized-element.ts';

/** What pasting gives the dashboard: the codes' exports as files, and the codes that could not be read. */
export interface PastedCodes {
  files: DroppedFile[];
  skipped: SkippedFile[];
}

/**
 * @summary Results codes pasted (results-code.ts): the teacher copies the answers of their
 * form (a column, or all of it: the codes are picked out of any text) and the dashboard reads
 * each code as the results file it stands for.
 * @fires codes-pasted - detail: PastedCodes
 */
export class RtDashboardPasteCodes extends LocalizedElement {
  static override properties = {
    note: { state: true },
  };

  static override styles = [
    classroomStyles,
    codeBoxStyles,
    css`
      :host {
        display: grid;
        gap: var(--rt-space);
        margin-top: calc(var(--rt-space) * 2);
      }
      .row {
        display: flex;
        flex-wrap: wrap;
        gap: var(--rt-space);
        align-items: center;
      }
      p {
        margin: 0;
      }
    `,
  ];

  /** What the last reading found, for the status line. */
  declare note: string;
  /** Codes are numbered across pastes, so that "results code 3" names one code all along. */
  private count = 0;

  constructor() {
    super();
    this.note = '';
  }

  private read(): void {
    const area = this.renderRoot.querySelector('textarea')!;
    const codes = findResultsCodes(area.value);
    if (codes.length === 0) {
      this.note = msg(str`No results code found: a code starts with ${RESULTS_CODE_PREFIX}`);
      return;
    }
    const pasted: PastedCodes = { files: [], skipped: [] };
    for (const code of codes) {
      this.count += 1;
      const name = msg(str`results code ${this.count}`);
      const text = decodeResultsCode(code);
      if (text === null) pasted.skipped.push({ file: name, reason: msg('the code is incomplete or damaged: ask the student to copy all of it again') });
      else pasted.files.push({ name, text });
    }
    this.note = codes.length === 1 ? msg('1 code read.') : msg(str`${codes.length} codes read.`);
    area.value = '';
    this.dispatchEvent(new CustomEvent<PastedCodes>('codes-pasted', { detail: pasted, bubbles: true, composed: true }));
  }

  override render() {
    return html`<label>
        ${msg('Or paste results codes (from your form: one code, a column, or everything at once)')}
        <textarea class="codes" spellcheck="false" placeholder=${`${RESULTS_CODE_PREFIX}…`}></textarea>
      </label>
      <div class="row">
        <button type="button" @click=${this.read}>${msg('Read the codes')}</button>
        <p aria-live="polite">${this.note}</p>
      </div>`;
  }
}

customElements.define('rt-dashboard-paste-codes', RtDashboardPasteCodes);

declare global {
  interface HTMLElementTagNameMap {
    'rt-dashboard-paste-codes': RtDashboardPasteCodes;
  }
}
