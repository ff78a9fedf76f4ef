import { msg, str } from '@lit/localize';
import { html, nothing } from 'lit';
import { LocalizedElement } from '../../controls/localized-element.ts';
import { loadBrowserCatalog } from '../../../app/level-catalog-browser.ts';
import { readClassFiles, type ClassFiles, type DroppedFile } from '../../../classroom/dashboard-class.ts';
import { classLearners, filterLearners, type ClassLearner, type LearnerFilter } from '../../../classroom/dashboard-learners.ts';
import { learnerFilter } from './learner-filter.ts';
import { MAX_EXPORT_BYTES } from '../../../classroom/dashboard-read-file.ts';
import type { SkippedFile } from '../../../classroom/dashboard-record.ts';
import { isOptionalTask, learnerInLevel, summarizeLevels, type LevelSummary } from '../../../classroom/dashboard-summary.ts';
import { stickingPoints, STUCK_MIN_LEARNERS, STUCK_MIN_SHARE, STUCK_TIMES_TYPICAL } from '../../../classroom/dashboard-stuck.ts';
import { summarizeSurveys, type SurveysSummary } from '../../../classroom/dashboard-survey.ts';
import { issueText } from '../../../i18n/issue-text.ts';
import { studentsCounted } from '../../../i18n/counted.ts';
import { respondentsText, unknownSurveyText } from './survey-respondents.ts';
import { currentLocale } from '../../../i18n/locale.ts';
import { surveyById } from '../../../classroom/surveys.ts';
import { localize, type Locale } from '../../../quest/localized-text.ts';
import { plainLevelText } from '../../../quest/text-markup.ts';
import { playableLevels } from '../../../quest/level-index.ts';
import { dashboardPageStyles } from './dashboard-page.css.ts';
import './rt-dashboard-class-list.ts';
import './rt-dashboard-completion.ts';
import type { PastedCodes } from './rt-dashboard-paste-codes.ts';
import './rt-dashboard-paste-codes.ts';
import './rt-dashboard-gain.ts';
import { learnerLabel } from './rt-dashboard-level-times.ts';
import { formatDuration } from './rt-dashboard-format.ts';
import './rt-dashboard-stuck.ts';
import './rt-dashboard-survey.ts';
import './rt-dashboard-times.ts';
import '../../controls/rt-theme-toggle.ts';
import './rt-dashboard-quiz.ts';
import './rt-dashboard-challenges.ts';
import './rt-dashboard-code-labs.ts';
import { researchDownloads, type ClassCsvKind } from './dashboard-research-files.ts';
import { summarizeQuizzes, type QuizSummary } from '../../../classroom/dashboard-quiz.ts';
import { keepClassMinutes } from '../teacher-minutes.ts';

/** Level and task titles by id, for labels; an id the app does not know is shown as it is. */
function levelNames(locale: Locale) {
  const levels = new Map(playableLevels(loadBrowserCatalog()).map((level) => [level.id, level]));
  return {
    level: (id: string) => {
      const level = levels.get(id);
      return level ? plainLevelText(level.title, locale) : id;
    },
    task: (levelId: string, id: string) => {
      const task = levels.get(levelId)?.tasks.find((candidate) => candidate.id === id);
      return task ? plainLevelText(task.title, locale) : id;
    },
  };
}

/**
 * @summary The class dashboard (route #/dashboard): a teacher drops the export files of a
 * class (JSON or CSV, tens to hundreds) and sees time per level and task, where learners got
 * stuck, completion and the survey answers; files that are not exports are listed with the
 * reason and skipped. Everything is read in the browser; nothing is uploaded.
 */
export class RtDashboardPage extends LocalizedElement {
  static override properties = {
    files: { state: true },
    reading: { state: true },
    dragging: { state: true },
    filter: { state: true },
    locale: {},
  };

  static override styles = dashboardPageStyles;

  declare files: ClassFiles;
  declare reading: boolean;
  declare dragging: boolean;
  /** Which assignment and class are shown. */
  declare filter: LearnerFilter;
  /** The language of level titles and survey texts. */
  declare locale: Locale;

  /** Texts already read, to count an export dropped twice once. */
  private seen = new Map<string, string>();
  /** Every learner of the files read, each counted once; `shown` those the filter keeps. */
  private learners: ClassLearner[] = [];
  private shown: ClassLearner[] = [];
  private levels: LevelSummary[] = [];
  private surveys: SurveysSummary = { surveys: [], unknown: [] };
  private quizzes: QuizSummary[] = [];

  constructor() {
    super();
    this.files = { records: [], skipped: [] };
    this.reading = false;
    this.dragging = false;
    this.filter = { assignmentId: null, classCode: null };
    // The page's language: a Dutch teacher reads the levels' and tasks' Dutch titles.
    this.locale = currentLocale();
  }

  protected override willUpdate(changed: Map<PropertyKey, unknown>): void {
    if (changed.has('files')) this.learners = classLearners(this.files.records);
    // Kept for the teacher page's typical minutes per level (teacher-minutes.ts).
    if (changed.has('files')) keepClassMinutes(this.learners);
    if (changed.has('files') || changed.has('filter')) {
      this.shown = filterLearners(this.learners, this.filter);
      this.levels = summarizeLevels(this.shown);
      this.surveys = summarizeSurveys(this.shown, surveyById);
    }
    if (changed.has('files') || changed.has('filter') || changed.has('locale'))
      this.quizzes = summarizeQuizzes(this.shown, researchDownloads.questions(this.locale));
  }

  /** Reads dropped or chosen files and adds them to the class (public: tests and other pages may call it). */
  async addFiles(list: Iterable<File>): Promise<void> {
    this.reading = true;
    const tooBig: SkippedFile[] = [];
    const dropped: DroppedFile[] = [];
    await Promise.all(
      [...list].map(async (file) => {
        if (file.size > MAX_EXPORT_BYTES) tooBig.push({ file: file.name, reason: msg(str`too large for an export (${Math.round(file.size / 1048576)} MB)`) });
        else dropped.push({ name: file.name, text: await file.text() });
      }),
    );
    // Files finish reading in any order; sorting by name keeps the list and the CSV stable.
    dropped.sort((a, b) => a.name.localeCompare(b.name, 'en', { numeric: true }));
    const read = readClassFiles(dropped, this.files, this.seen);
    this.files = { records: read.records, skipped: [...read.skipped, ...tooBig] };
    this.reading = false;
  }

  /** Adds the exports of pasted results codes, as if their files were dropped. */
  private onCodesPasted(event: CustomEvent<PastedCodes>): void {
    const read = readClassFiles(event.detail.files, this.files, this.seen);
    this.files = { records: read.records, skipped: [...read.skipped, ...event.detail.skipped] };
  }

  private clear(): void {
    this.seen = new Map();
    this.files = { records: [], skipped: [] };
    this.filter = { assignmentId: null, classCode: null };
  }

  private onDrop(event: DragEvent): void {
    event.preventDefault();
    this.dragging = false;
    if (event.dataTransfer?.files.length) void this.addFiles(event.dataTransfer.files);
  }

  private onDragOver(event: DragEvent): void {
    event.preventDefault();
    if (event.dataTransfer) event.dataTransfer.dropEffect = 'copy';
    this.dragging = true;
  }

  private onChoose(event: Event): void {
    const input = event.target as HTMLInputElement;
    if (input.files?.length) void this.addFiles(input.files).then(() => (input.value = ''));
  }

  private downloadCsv(kind: ClassCsvKind): void {
    const freeText = this.renderRoot.querySelector<HTMLInputElement>('input[name="free-text"]')?.checked ?? false;
    researchDownloads.classCsv(kind, this.shown, this.locale, freeText);
  }

  /** "3 learners counted (5 files, 2 merged into their learner's), 1 file skipped." */
  private statusText(): string {
    const { records, skipped } = this.files;
    const learners = this.learners.length;
    const merged = records.length - learners;
    const counted = learners === 1 ? msg('1 student counted') : msg(str`${learners} students counted`);
    const files =
      merged === 0
        ? ''
        : merged === 1
          ? msg(str` (from ${records.length} files: 1 merged into its student's)`)
          : msg(str` (from ${records.length} files: ${merged} merged into their student's)`);
    const skippedText = skipped.length === 1 ? msg('1 file skipped.') : msg(str`${skipped.length} files skipped.`);
    return `${counted}${files}, ${skippedText}`;
  }

  override render() {
    const { records, skipped } = this.files;
    return html`
      <header>
        <h1>${msg('Class dashboard')}</h1>
        <a class="button" href="#/">${msg('Back to the game')}</a>
        <rt-theme-toggle></rt-theme-toggle>
      </header>
      <main>
        <section aria-labelledby="files-heading">
          <h2 id="files-heading">${msg('Export files')}</h2>
          <div
            class="drop ${this.dragging ? 'dragging' : ''}"
            @dragover=${this.onDragOver}
            @dragleave=${() => (this.dragging = false)}
            @drop=${this.onDrop}
          >
            <p>${msg('Drop the files your students exported from the game here: JSON or CSV, as many as you like. You can drop more later; they are added.')}</p>
            <label class="button primary" title=${msg('Pick export files from your computer')}>
              ${msg('Choose files…')}
              <input type="file" multiple accept=".json,.csv,application/json,text/csv" @change=${this.onChoose} />
            </label>
          </div>
          <rt-dashboard-paste-codes @codes-pasted=${this.onCodesPasted}></rt-dashboard-paste-codes>
          <p class="privacy">
            <svg viewBox="0 0 16 16" width="16" height="16" aria-hidden="true">
              <rect x="3" y="7" width="10" height="7" rx="1.5" fill="none" stroke="currentColor" stroke-width="1.5" />
              <path d="M5 7V5a3 3 0 0 1 6 0v2" fill="none" stroke="currentColor" stroke-width="1.5" />
            </svg>
            ${msg('The files are read in this browser only. Nothing is uploaded or sent anywhere.')}
          </p>
          <p class="status" role="status">
            ${this.reading ? msg('Reading the files…') : records.length + skipped.length > 0 ? this.statusText() : ''}
          </p>
          ${learnerFilter(this.learners, this.shown.length, this.filter, (changes) => (this.filter = { ...this.filter, ...changes }))}
          <div class="actions">
            <button type="button" ?disabled=${this.shown.length === 0} @click=${() => this.downloadCsv('class')} title=${msg('One CSV with every task attempt of every student shown, for a spreadsheet or R')}>
              ${msg('Download combined CSV')}
            </button>
            <button type="button" ?disabled=${!this.shown.some((learner) => learner.survey)} @click=${() => this.downloadCsv('survey')} title=${msg('One row per student shown who answered the survey, one column per question')}>
              ${msg('Download survey CSV')}
            </button>
            <button type="button" ?disabled=${this.shown.length === 0} @click=${() => researchDownloads.learnerLevels(this.shown, this.levels)} title=${msg('One row per student and level: time, passed, tasks, hints, quiz answers')}>
              ${msg('Download student × level CSV')}
            </button>
            <button type="button" @click=${() => researchDownloads.codebook(this.locale)} title=${msg('What every column, quiz option and survey answer in the downloads means')}>
              ${msg('Download codebook')}
            </button>
            <button type="button" ?disabled=${this.shown.length === 0} @click=${() => this.downloadCsv('research')} title=${msg('The combined CSV for a study: times in seconds from the start instead of dates and clock times, no device id, no file names')}>
              ${msg('Download research CSV')}
            </button>
            <label><input type="checkbox" name="free-text" /> ${msg('with free-text answers (marked)')}</label>
            <button type="button" ?disabled=${records.length + skipped.length === 0} @click=${this.clear} title=${msg('Forget the files read so far and start again')}>
              ${msg('Clear')}
            </button>
          </div>
        </section>
        <section aria-labelledby="class-list-heading">
          <h2 id="class-list-heading">${msg('Class list: who has handed in')}</h2>
          <rt-dashboard-class-list .learners=${this.shown}></rt-dashboard-class-list>
        </section>
        ${skipped.length ? this.renderSkipped(skipped) : null} ${this.renderLearnerTimes()} ${this.levels.map((level) => this.renderLevel(level))}
        ${this.shown.some((learner) => learner.conceptTest) ? html`<section aria-labelledby="gain-heading"><h2 id="gain-heading">${msg('Concept test: learning measured')}</h2><rt-dashboard-gain .learners=${this.shown} .locale=${this.locale}></rt-dashboard-gain></section>` : nothing}
        ${this.renderSurveys()}
      </main>
    `;
  }

  /** Time per level per learner, every level side by side. */
  private renderLearnerTimes() {
    if (this.shown.length === 0 || this.levels.length === 0) return nothing;
    const names = levelNames(this.locale);
    const rows = this.shown.map((learner) => ({ learner: learnerLabel(learner), cells: this.levels.map((level) => learnerInLevel(learner, level.level)) }));
    return html`<section class="learner-times" aria-labelledby="learner-times-heading">
      <h2 id="learner-times-heading">${msg('Time per level, per student')}</h2>
      <!-- A long class folds away, so the levels below stay in reach. -->
      <details ?open=${this.shown.length <= 40}>
        <summary>${studentsCounted(this.shown.length)}</summary>
        <rt-dashboard-level-times
          .rows=${rows}
          .levels=${this.levels.map((level) => names.level(level.level))}
          caption=${msg('Active time of each student in each level; a striped bar: not passed (yet)')}
        ></rt-dashboard-level-times>
      </details>
    </section>`;
  }

  private renderSkipped(skipped: readonly SkippedFile[]) {
    return html`<section class="skipped-files" aria-labelledby="skipped-heading">
      <h2 id="skipped-heading">⚠ ${msg(str`Skipped files (${skipped.length})`)}</h2>
      <table class="skipped">
        <thead>
          <tr>
            <th scope="col">${msg('File')}</th>
            <th scope="col">${msg('Why it was skipped')}</th>
          </tr>
        </thead>
        <tbody>
          ${skipped.map((file) => html`<tr><td>${file.file}</td><td>${file.detail === undefined ? file.reason : `${file.reason}: ${issueText(file.detail)}`}</td></tr>`)}
        </tbody>
      </table>
    </section>`;
  }

  private renderLevel(level: LevelSummary) {
    const names = levelNames(this.locale);
    const title = names.level(level.level);
    const stuck = stickingPoints(level.tasks);
    const rows = level.tasks.map((task) => ({
      ...task,
      label: isOptionalTask(task) ? msg(str`${names.task(level.level, task.task)} (optional)`) : names.task(level.level, task.task),
    }));
    return html`<section class="level" data-level=${level.level} aria-label=${title}>
      <h2>${title}</h2>
      <p class="level-facts">
        ${msg(str`${level.passed} of ${level.learners} students passed`)}${
          level.stats
            ? msg(
                str`; median active time ${formatDuration(level.stats.median)} (middle half ${formatDuration(level.stats.q1)} – ${formatDuration(level.stats.q3)})`,
              )
            : ''
        }
      </p>
      <h3>${msg('Active time per task')}</h3>
      <rt-dashboard-times
        .rows=${rows}
        caption=${msg(str`Active time per task in ${title}: a box for the middle half, a line for the median, a dot per student`)}
      ></rt-dashboard-times>
      <h3>${msg('Active time for the whole level (students who passed)')}</h3>
      <rt-dashboard-times
        class="whole-level"
        .rows=${[{ label: msg('Whole level'), times: level.times, stats: level.stats }]}
        caption=${msg(str`Active time for the whole of ${title}, of the students who passed it`)}
      ></rt-dashboard-times>
      <h3>${msg('Completion')}</h3>
      <rt-dashboard-completion .rows=${rows} caption=${msg(str`Completion per task in ${title}`)}></rt-dashboard-completion>
      ${this.renderQuizzes(level.level, title)}
      <rt-dashboard-challenges .records=${this.shown} level=${level.level} .taskName=${(task: string) => names.task(level.level, task)}></rt-dashboard-challenges>
      <rt-dashboard-code-labs .records=${this.shown} level=${level.level} .taskName=${(task: string) => names.task(level.level, task)}></rt-dashboard-code-labs>
      <h3>${msg('Where students got stuck')}</h3>
      <p class="rule">${stuckRule()}</p>
      <rt-dashboard-stuck
        .rows=${rows.map((row) => ({ ...row, task: names.task(level.level, row.task), stuck: stuck.has(row.task) }))}
        caption=${msg(str`Hints, "show me" and times per task in ${title}`)}
      ></rt-dashboard-stuck>
    </section>`;
  }

  private renderQuizzes(levelId: string, title: string) {
    const quizzes = this.quizzes.filter((quiz) => quiz.level === levelId);
    if (quizzes.length === 0) return nothing;
    return html`<h3>${msg('Quiz answers')}</h3>
      <rt-dashboard-quiz .rows=${quizzes} caption=${msg(str`Answers per quiz question in ${title}`)}></rt-dashboard-quiz>`;
  }

  private renderSurveys() {
    const { surveys, unknown } = this.surveys;
    return html`${surveys.map(
      (survey) => html`<section class="survey" data-survey=${survey.id}>
        <h2>${msg(str`Survey: ${localize(survey.title, this.locale)}`)}</h2>
        <p class="level-facts">${respondentsText(survey.respondents)}</p>
        <rt-dashboard-survey .summary=${survey} .locale=${this.locale}></rt-dashboard-survey>
      </section>`,
    )}
    ${unknown.map((survey) => html`<section><p>⚠ ${unknownSurveyText(survey.respondents, survey.id)}</p></section>`)}`;
  }
}

/** The sticking-point rule (classroom/dashboard-stuck.ts), in words. */
function stuckRule(): string {
  const share = `${Math.round(STUCK_MIN_SHARE * 100)} %`;
  return msg(
    str`⚠ marks a sticking point: a required task where at least ${share} of the students needed help (a hint they opened, "show me", or they did not finish it) and at least ${STUCK_TIMES_TYPICAL} times as many as on a typical task of this level (the median). A hint offered after idling counts only when the student opened it. Tasks seen by fewer than ${STUCK_MIN_LEARNERS} students are not marked.`,
  );
}

customElements.define('rt-dashboard-page', RtDashboardPage);

declare global {
  interface HTMLElementTagNameMap {
    'rt-dashboard-page': RtDashboardPage;
  }
}
