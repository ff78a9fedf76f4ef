import { msg, str } from '@lit/localize';
import { css, html, nothing } from 'lit';
import { LocalizedElement } from '../controls/localized-element.ts';
import { codeBoxStyles } from './code-box.css.ts';
import { loadBrowserCatalog } from '../../app/level-catalog-browser.ts';
import type { Assignment } from '../../classroom/assignment.ts';
import { choiceQuestions, optionTexts } from '../../classroom/quiz-options.ts';
import { playableLevels } from '../../quest/level-index.ts';
import { downloadText } from '../../util/download-file.ts';
import { exportFileName } from '../../classroom/export-file-name.ts';
import { APP_VERSION, type ExportInput } from '../../classroom/export-context.ts';
import type { ConceptTestAnswers } from '../../classroom/concept-test/concept-answers.ts';
import type { ExportFormat } from '../../classroom/export-files.ts';
import { exportInstallId, randomUuid } from '../../classroom/learner-identity.ts';
import type { SurveySubmission } from '../../classroom/survey-answers.ts';
import { MemoryStorage } from '../../quest/progress-store.ts';
import type { Progress } from '../../quest/progress.ts';

type Format = ExportFormat;

/** The exporters, loaded at the first click (export-files.ts). */
const exportFiles = () => import('../../classroom/export-files.ts');

/**
 * @summary Handing in the results: one results file (the JSON export: everything, with the
 * full event log and the survey; the dashboard reads it), or the same as a results code to
 * paste into a form (results-code.ts). CSV (one row per task attempt) and xAPI statements stay
 * below as other formats, for researchers. Made in the browser from the current progress;
 * nothing is uploaded. Set `.progress` (QuestEngine.progress, read at the moment of the click) and the
 * classroom context: `.participant`, `.attemptId`, `.assignment`, `.survey`; without a
 * participant code the browser's install id is read from localStorage.
 * @fires export-failed - detail: the message, when a file could not be made (the lab shows it as a toast).
 */
export class RtExportMenu extends LocalizedElement {
  static override properties = {
    progress: { attribute: false },
    participant: { attribute: false },
    attemptId: { attribute: false },
    assignment: { attribute: false },
    survey: { attribute: false },
    code: { state: true },
    copied: { state: true },
    conceptTest: { attribute: false },
  };

  static override styles = [
    codeBoxStyles,
    css`
    :host {
      display: grid;
      gap: var(--rt-space);
      --code-box-height: 5em;
    }
    .row {
      display: flex;
      flex-wrap: wrap;
      align-items: center;
      gap: var(--rt-space);
    }
    .primary {
      background: var(--rt-accent);
      border-color: var(--rt-accent);
      color: var(--rt-accent-text);
      font-weight: 600;
    }
    .primary:hover {
      background: var(--rt-accent);
      filter: brightness(1.1);
    }
    p {
      margin: 0;
      font-size: 0.9em;
      color: var(--rt-muted);
    }
    .research button {
      min-height: 28px;
      font-size: 0.9em;
    }
    button {
      font: inherit;
      min-height: 36px;
      padding: 4px 12px;
      border-radius: var(--rt-radius);
      border: 1px solid var(--rt-border);
      background: var(--rt-surface);
      color: var(--rt-text);
      cursor: pointer;
    }
    button:hover {
      background: var(--rt-surface-2, var(--rt-surface));
    }
    button:focus-visible {
      outline: 3px solid var(--rt-focus, var(--rt-accent));
      outline-offset: 2px;
    }
    button:disabled {
      cursor: not-allowed;
      opacity: 0.6;
    }
  `,
  ];

  /** The progress to export; a function is called at the click, so the file has the latest events. */
  declare progress: Progress | (() => Progress) | null;
  declare participant: string | null;
  /** The playthrough's id (QuestSession.context.attemptId); a missing one gets an id for this page. */
  declare attemptId: string | null;
  declare assignment: Assignment | null;
  declare survey: SurveySubmission | null;
  /** The results code last made, shown so that it can also be copied by hand. */
  declare code: string | null;
  /** Whether the browser put the code on the clipboard itself. */
  declare copied: boolean;
  declare conceptTest: ConceptTestAnswers | null;

  constructor() {
    super();
    this.progress = null;
    this.participant = null;
    this.attemptId = null;
    this.assignment = null;
    this.survey = null;
    this.code = null;
    this.copied = false;
    this.conceptTest = null;
  }

  /** The file of one format, exactly as the buttons download it (for tests and other menus). */
  async fileOf(format: Format): Promise<{ name: string; text: string; type: string } | null> {
    const { EXPORT_FILES } = await exportFiles();
    const input = this.exportInput();
    if (!input) return null;
    const file = EXPORT_FILES[format];
    const name = exportFileName(this.participant, this.assignment?.title ?? null, new Date(input.exportedAt), file.extension);
    return { name, text: file.text(input), type: file.type };
  }

  /** The results code of the current progress (results-code.ts), or null without progress. */
  async codeOf(): Promise<string | null> {
    const { resultsCode } = await exportFiles();
    const input = this.exportInput();
    return input && resultsCode(input);
  }

  private exportInput(): ExportInput | null {
    const progress = typeof this.progress === 'function' ? this.progress() : this.progress;
    if (!progress) return null;
    this.attemptId ??= randomUuid();
    const exportedAt = new Date();
    return {
      progress,
      participant: this.participant,
      installId: exportInstallId(this.participant, browserStorage()),
      attemptId: this.attemptId,
      assignment: this.assignment,
      survey: this.survey,
      exportedAt: exportedAt.toISOString(),
      conceptTest: this.conceptTest,
      appVersion: APP_VERSION,
      utcOffsetMin: -exportedAt.getTimezoneOffset(),
      // The options' texts in the language the levels are loaded in: the one the learner played in.
      optionText: optionTexts(choiceQuestions(playableLevels(loadBrowserCatalog()), this.assignment?.locale ?? progress.settings.locale)),
    };
  }

  private async download(format: Format): Promise<void> {
    try {
      const file = await this.fileOf(format);
      if (file) downloadText(file.text, file.name, file.type);
    } catch (error) {
      this.failed(error);
    }
  }

  private async copyCode(): Promise<void> {
    try {
      this.code = await this.codeOf();
    } catch (error) {
      this.failed(error);
      return;
    }
    if (this.code === null) return;
    this.copied = false;
    try {
      // Refused on a page served over plain http and in some browsers' settings: the code is then shown selected, to copy by hand.
      await navigator.clipboard.writeText(this.code);
      this.copied = true;
    } catch {
      await this.updateComplete;
      this.renderRoot.querySelector('textarea')?.select();
    }
  }

  private failed(error: unknown): void {
    const reason = error instanceof Error ? error.message : String(error);
    this.dispatchEvent(new CustomEvent('export-failed', { detail: msg(str`The results could not be exported: ${reason}`), bubbles: true, composed: true }));
  }

  override render() {
    const none = this.progress === null;
    return html`
      <div class="row">
        <button
          type="button"
          class="primary"
          ?disabled=${none}
          @click=${() => this.download('json')}
          title=${msg('One file with all your results and survey answers, named with your code: hand this file in')}
        >
          ${msg('Download results file')}
        </button>
        <button type="button" ?disabled=${none} @click=${() => void this.copyCode()} title=${msg('The same results as one line of text, to paste into the form your teacher gave you')}>
          ${msg('Copy results code')}
        </button>
      </div>
      <p>${msg('Hand in what your teacher asked for: the file, or the code pasted into their form. Both hold the same results.')}</p>
      ${
        this.code === null
          ? nothing
          : html`<p aria-live="polite">
              ${this.copied ? msg('Copied. Paste it into the form your teacher gave you (Ctrl+V).') : msg('Select all of the code below and copy it (Ctrl+C).')}
            </p>
            <textarea class="codes" readonly aria-label=${msg('Your results code')} @focus=${(event: FocusEvent) => (event.target as HTMLTextAreaElement).select()} .value=${this.code}></textarea>`
      }
      <div class="row research">
        <p>${msg('Other formats, for research:')}</p>
        <button type="button" ?disabled=${none} @click=${() => this.download('csv')} title=${msg('One row per task attempt, with times and hints: for a spreadsheet')}>
          ${msg('Download CSV')}
        </button>
        <button type="button" ?disabled=${none} @click=${() => this.download('xapi')} title=${msg("xAPI statements, for your school's learning record store")}>
          ${msg('Download xAPI')}
        </button>
      </div>
    `;
  }
}

/** localStorage, or storage for this page when the browser blocks it. */
function browserStorage(): Storage | MemoryStorage {
  try {
    return localStorage;
  } catch {
    return new MemoryStorage();
  }
}

customElements.define('rt-export-menu', RtExportMenu);

declare global {
  interface HTMLElementTagNameMap {
    'rt-export-menu': RtExportMenu;
  }
}
