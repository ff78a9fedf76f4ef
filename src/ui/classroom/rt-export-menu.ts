import { msg, str } from '@lit/localize';
import { css, html, LitElement } from 'lit';
import { loadBrowserCatalog } from '../../app/level-catalog-browser.ts';
import type { Assignment } from '../../classroom/assignment.ts';
import { choiceQuestions, optionTexts } from '../../classroom/quiz-options.ts';
import { playableLevels } from '../../quest/level-index.ts';
import { downloadText } from '../../util/download-file.ts';
import { exportFileName } from '../../classroom/export-file-name.ts';
import { APP_VERSION, type ExportInput } from '../../classroom/export-context.ts';
import { exportCsv } from '../../classroom/export-csv.ts';
import { exportJson } from '../../classroom/export-json.ts';
import { exportXapi } from '../../classroom/export-xapi.ts';
import { installId, randomUuid } from '../../classroom/learner-identity.ts';
import type { SurveySubmission } from '../../classroom/survey-answers.ts';
import { MemoryStorage } from '../../quest/progress-store.ts';
import type { Progress } from '../../quest/progress.ts';

type Format = 'csv' | 'json' | 'xapi';

const FILES: Record<Format, { extension: string; type: string; text: (input: ExportInput) => string }> = {
  csv: { extension: 'csv', type: 'text/csv;charset=utf-8', text: exportCsv },
  json: { extension: 'json', type: 'application/json', text: exportJson },
  xapi: { extension: 'xapi.json', type: 'application/json', text: (input) => `${JSON.stringify(exportXapi(input), null, 2)}\n` },
};

/**
 * @summary The results downloads: CSV (one row per task attempt), JSON (everything, with the
 * full event log) and xAPI statements. Made in the browser from the current progress; nothing
 * is uploaded. Set `.progress` (QuestEngine.progress, read at the moment of the click) and the
 * classroom context: `.participant`, `.attemptId`, `.assignment`, `.survey`; the browser's
 * install id is read from localStorage.
 * @fires export-failed - detail: the message, when a file could not be made (the lab shows it as a toast).
 */
export class RtExportMenu extends LitElement {
  static override properties = {
    progress: { attribute: false },
    participant: { attribute: false },
    attemptId: { attribute: false },
    assignment: { attribute: false },
    survey: { attribute: false },
  };

  static override styles = css`
    :host {
      display: flex;
      flex-wrap: wrap;
      gap: var(--rt-space);
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
  `;

  /** The progress to export; a function is called at the click, so the file has the latest events. */
  declare progress: Progress | (() => Progress) | null;
  declare participant: string | null;
  /** The playthrough's id (QuestSession.context.attemptId); a missing one gets an id for this page. */
  declare attemptId: string | null;
  declare assignment: Assignment | null;
  declare survey: SurveySubmission | null;

  constructor() {
    super();
    this.progress = null;
    this.participant = null;
    this.attemptId = null;
    this.assignment = null;
    this.survey = null;
  }

  /** The file of one format, exactly as the buttons download it (for tests and other menus). */
  fileOf(format: Format): { name: string; text: string; type: string } | null {
    const progress = typeof this.progress === 'function' ? this.progress() : this.progress;
    if (!progress) return null;
    const exportedAt = new Date().toISOString();
    this.attemptId ??= randomUuid();
    const input: ExportInput = {
      progress,
      participant: this.participant,
      installId: installId(browserStorage()),
      attemptId: this.attemptId,
      assignment: this.assignment,
      survey: this.survey,
      exportedAt,
      appVersion: APP_VERSION,
      utcOffsetMin: -new Date(exportedAt).getTimezoneOffset(),
      // The options' texts in the language the levels are loaded in: the one the learner played in.
      optionText: optionTexts(choiceQuestions(playableLevels(loadBrowserCatalog()), this.assignment?.locale ?? progress.settings.locale)),
    };
    const file = FILES[format];
    return { name: exportFileName(this.participant, exportedAt, file.extension), text: file.text(input), type: file.type };
  }

  private download(format: Format): void {
    try {
      const file = this.fileOf(format);
      if (file) downloadText(file.text, file.name, file.type);
    } catch (error) {
      const reason = error instanceof Error ? error.message : String(error);
      this.dispatchEvent(new CustomEvent('export-failed', { detail: msg(str`The results could not be exported: ${reason}`), bubbles: true, composed: true }));
    }
  }

  override render() {
    const none = this.progress === null;
    return html`
      <button type="button" ?disabled=${none} @click=${() => this.download('csv')} title=${msg('One row per task attempt, with times and hints: for a spreadsheet')}>
        ${msg('Download CSV')}
      </button>
      <button type="button" ?disabled=${none} @click=${() => this.download('json')} title=${msg('Everything, with the full event log and survey answers: for the class dashboard')}>
        ${msg('Download JSON')}
      </button>
      <button type="button" ?disabled=${none} @click=${() => this.download('xapi')} title=${msg("xAPI statements, for your school's learning record store")}>
        ${msg('Download xAPI')}
      </button>
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
