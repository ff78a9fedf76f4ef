import { msg, str } from '@lit/localize';
import { html, nothing } from 'lit';
import { LocalizedElement } from '../controls/localized-element.ts';
import QRCode from 'qrcode';
import { loadBrowserCatalog, loadBrowserLevelGuide } from '../../app/level-catalog-browser.ts';
import type { Assignment } from '../../classroom/assignment.ts';
import { TITLE_MAX } from '../../classroom/assignment-schema.ts';
import { compactAssignment } from '../../classroom/assignment-compact.ts';
import { mandatoryTasks, withPreset } from '../../classroom/assignment-preset.ts';
import { assignmentUrl, decodeAssignment } from '../../classroom/assignment-link.ts';
import { assignmentId } from '../../classroom/assignment-id.ts';
import { expandAssignment } from '../../classroom/assignment-expand.ts';
import { assignmentHashOfTeacherLink, teacherLinkHash } from '../../classroom/teacher-link.ts';
import type { Level } from '../../quest/level-schema.ts';
import { playableLevels, type LevelPreset } from '../../quest/level-index.ts';
import { currentLocale } from '../../i18n/locale.ts';
import { plainLevelText } from '../../quest/text-markup.ts';
import { localize } from '../../quest/localized-text.ts';
import { issueText } from '../../i18n/issue-text.ts';
import { shortList } from '../../i18n/short-list.ts';
import { teacherPageStyles } from './teacher-page.css.ts';
import { TeacherKeeper } from './teacher-keeper.ts';
import { levelItem } from './teacher-level-item.ts';
import { MeasuredMinutesController, totalMinutesText } from './teacher-minutes.ts';
import { afterLessonSection, optional, researchSection, settingsSection } from './teacher-sections.ts';
import type { ShelfRequest } from './rt-teacher-shelf.ts';
import '../controls/rt-theme-toggle.ts';
import { consentSection } from './teacher-consent-section.ts';
import { assignmentProblem } from './teacher-assignment-problem.ts';
import './rt-scorm-download.ts';
import './rt-teacher-concept-test.ts';
import './rt-teacher-handout.ts';
import './rt-teacher-shelf.ts';

/**
 * @summary The teacher page (`#/teacher`): builds an assignment — title, levels and their
 * order (by hand or from a preset of levels/index.json, each level with its one idea, task
 * kinds, minutes and a preview), required tasks, other levels, language, participant code,
 * closing survey — and shows its link with a copy button, a QR code for the projector, a
 * link to try it as a student, a printable handout and the way to the dashboard.
 * Every assignment that makes a link is kept in this browser (teacher-keeper.ts) and the
 * page reopens the last one; nothing is sent anywhere: the link is the assignment.
 *
 * The page is a list of sections (`render`): a new part of the assignment is a function
 * `(assignment, change) => template` in a file of its own, added to that list with one line.
 */
export class RtTeacherPage extends LocalizedElement {
  static override properties = {
    assignment: { state: true },
    url: { state: true },
    qr: { state: true },
    status: { state: true },
    stale: { state: true },
    adding: { state: true },
  };

  static override styles = teacherPageStyles;

  declare assignment: Assignment;
  /** The student link, or null while it is being made or when the assignment cannot be made. */
  declare url: string | null;
  declare qr: string | null;
  declare status: string;
  /** A newer link is being made (compressing, drawing the QR code). */
  declare stale: boolean;
  /** The level chosen under "Add a level" (its idea is shown under the list), or '' for the first. */
  declare adding: string;

  private readonly levels: Level[] = playableLevels(loadBrowserCatalog());
  private readonly guide = loadBrowserLevelGuide();
  private readonly keeper = new TeacherKeeper(this);
  private readonly measured = new MeasuredMinutesController(this);
  private made = 0;

  constructor() {
    super();
    const latest = this.keeper.latest;
    this.assignment = latest?.assignment ?? this.newAssignment();
    if (latest) this.keeper.show(latest);
    else this.keeper.startNew(this.assignment);
    this.url = null;
    this.qr = null;
    this.status = '';
    this.stale = false;
    this.adding = '';
  }

  /** A first assignment: the first level, in the teacher's own language (a Dutch teacher's pupils get Dutch unless chosen otherwise). */
  private newAssignment(): Assignment {
    const first = this.levels[0];
    return {
      version: 1,
      title: msg('Ray tracing lesson'),
      levels: first ? [first.id] : [],
      requiredTasks: first ? { [first.id]: mandatoryTasks(first) } : {},
      otherLevels: 'hidden',
      locale: currentLocale(),
      askParticipantCode: false,
      survey: null,
    };
  }

  override connectedCallback(): void {
    super.connectedCallback();
    // Opened on an assignment (#/teacher/a/…): its form, and the plain address, so that a reload shows what was edited since.
    const opened = assignmentHashOfTeacherLink(location.hash);
    if (opened === null) return;
    history.replaceState(history.state, '', '#/teacher');
    void this.openLink(opened);
  }

  override willUpdate(changed: Map<string, unknown>): void {
    if (changed.has('assignment')) void this.makeLink();
  }

  override updated(): void {
    // The levels to add change as levels are added: keep the choice on the level whose idea is shown.
    const select = this.renderRoot.querySelector<HTMLSelectElement>('#add-level');
    const shown = this.renderRoot.querySelector<HTMLElement>('#add-level-idea')?.dataset.level;
    if (select && shown) select.value = shown;
  }

  /** The problem that keeps the assignment from being a link, or null. */
  private get problem(): string | null {
    return assignmentProblem(this.assignment);
  }

  private async makeLink(): Promise<void> {
    const run = ++this.made;
    // Until the new link is made, the one shown is out of date: it must not be copied or opened.
    this.stale = true;
    if (this.problem) {
      this.url = this.qr = null;
      this.keeper.notKept();
      return;
    }
    const made = { ...this.assignment, title: this.assignment.title.trim() };
    // Kept before the link is computed, not after: a reload right after typing finds the change.
    this.keeper.keep(made);
    const assignment = compactAssignment(made, this.levels);
    const url = await assignmentUrl(assignment, location.href);
    // Level L (7 % recovery) is enough for a projected code nothing covers, and gives the
    // fewest, largest squares: what matters from the back of a classroom.
    const svg = await QRCode.toString(url, { type: 'svg', errorCorrectionLevel: 'L', margin: 2 });
    // A newer change may have finished first: only the latest link is shown.
    if (run !== this.made) return;
    this.url = url;
    this.qr = `data:image/svg+xml;charset=utf-8,${encodeURIComponent(svg)}`;
    this.status = '';
    this.stale = false;
  }

  /** A request of the kept assignments' list: open, forget, start anew, open a link, copy for another class. */
  private async shelfRequest(request: ShelfRequest): Promise<void> {
    switch (request.kind) {
      case 'open': {
        const entry = this.keeper.entries.find((candidate) => candidate.id === request.id);
        if (entry) this.keeper.show(entry);
        if (entry) this.assignment = entry.assignment;
        return;
      }
      case 'remove':
        return this.keeper.remove(request.id);
      case 'new':
        this.assignment = this.newAssignment();
        return this.keeper.startNew(this.assignment);
      case 'copy':
        this.keeper.startNew();
        this.assignment = { ...this.assignment, title: request.title };
        return this.change({ classCode: optional(request.classCode) });
      case 'open-link':
        return this.openLink(request.link);
    }
  }

  /** A link pasted in: its assignment fills the form, as the one kept from it when there is one. */
  private async openLink(link: string): Promise<void> {
    const hash = link.slice(Math.max(0, link.indexOf('#')));
    const result = await decodeAssignment(hash, loadBrowserCatalog());
    if (!result.ok) return this.keeper.tellProblem(msg(str`This link did not open: ${shortList(result.reasons.map(issueText))}.`));
    const kept = this.keeper.entries.find((entry) => assignmentId(compactAssignment(entry.assignment, this.levels)) === assignmentId(result.assignment));
    if (kept) this.keeper.show(kept);
    else this.keeper.startNew();
    this.assignment = kept?.assignment ?? expandAssignment(result.assignment, this.levels);
  }

  /** What a section of the page calls with its changes to the assignment. */
  private readonly changer = (changes: Partial<Assignment>): void => this.change(changes);

  private change(changes: Partial<Assignment>): void {
    const next: Assignment = { ...this.assignment, ...changes };
    // An optional field left empty is left out, so the link (and the assignment's id) stays as without it.
    if (next.classCode === undefined) delete next.classCode;
    if (next.xapiHomePage === undefined) delete next.xapiHomePage;
    if (next.surveyQuestions === undefined) delete next.surveyQuestions;
    this.assignment = next;
  }

  private level(id: string): Level | undefined {
    return this.levels.find((level) => level.id === id);
  }

  private addLevel(id: string): void {
    const level = this.level(id);
    if (!level || this.assignment.levels.includes(id)) return;
    this.change({ levels: [...this.assignment.levels, id], requiredTasks: { ...this.assignment.requiredTasks, [id]: mandatoryTasks(level) } });
  }

  /** One click for a ready-made list: its levels replace the assignment's. */
  private usePreset(preset: LevelPreset): void {
    const { levels, requiredTasks } = withPreset(this.assignment, preset, this.levels);
    this.change({ levels, requiredTasks });
  }

  /** The level's one idea (levels/index.json), in the assignment's language. */
  private idea(id: string, locale: Assignment['locale']): string | null {
    const idea = this.guide.ideas[id];
    return idea === undefined ? null : localize(idea, locale);
  }

  private removeLevel(id: string): void {
    const { [id]: _removed, ...requiredTasks } = this.assignment.requiredTasks;
    this.change({ levels: this.assignment.levels.filter((other) => other !== id), requiredTasks });
  }

  private moveLevel(index: number, by: -1 | 1): void {
    const levels = [...this.assignment.levels];
    [levels[index], levels[index + by]] = [levels[index + by], levels[index]];
    this.change({ levels });
    // Keep the keyboard on the moved level's button.
    void this.updateComplete.then(() => this.renderRoot.querySelector<HTMLElement>(`[data-level="${levels[index + by]}"] [data-move="${by}"]`)?.focus());
  }

  private toggleTask(levelId: string, taskId: string, required: boolean): void {
    const level = this.level(levelId);
    const current = new Set(this.assignment.requiredTasks[levelId] ?? []);
    if (required) current.add(taskId);
    else current.delete(taskId);
    // In the level's order, so the link is the same however the boxes were ticked.
    const tasks = level ? level.tasks.map((task) => task.id).filter((id) => current.has(id)) : [...current];
    this.change({ requiredTasks: { ...this.assignment.requiredTasks, [levelId]: tasks } });
  }

  private async copy(): Promise<void> {
    if (!this.url) return;
    try {
      await navigator.clipboard.writeText(this.url);
      this.status = msg('Link copied.');
    } catch {
      // No clipboard permission (an http page, an old browser): select the text for Ctrl+C.
      const field = this.renderRoot.querySelector<HTMLInputElement>('input.link');
      field?.select();
      this.status = msg('Press Ctrl+C (or ⌘C) to copy the selected link.');
    }
  }

  override render() {
    return html`
      <header>
        <h1>${msg('Make an assignment')}</h1>
        <a class="button" href="#/">${msg('Back to the game')}</a>
        <rt-theme-toggle></rt-theme-toggle>
      </header>
      <main>
        <div class="form">${this.renderKept()} ${this.renderTitle()} ${this.renderLevels()} ${settingsSection(this.assignment, this.changer)} ${researchSection(this.assignment, this.changer)} ${consentSection(this.assignment, (consent) => this.change({ consent }))}
          <rt-teacher-concept-test .value=${this.assignment.conceptTest} @concept-test-change=${(e: CustomEvent<Assignment['conceptTest']>) => this.change({ conceptTest: e.detail })}></rt-teacher-concept-test>
        </div>
        <div class="result">${this.renderLink()} ${this.renderHandout()} ${afterLessonSection()}</div>
      </main>
    `;
  }

  private renderKept() {
    return html`<section aria-labelledby="kept-heading">
      <h2 id="kept-heading">${msg('Your assignments (kept in this browser)')}</h2>
      <rt-teacher-shelf
        .entries=${this.keeper.entries}
        .current=${this.keeper.id}
        .status=${this.keeper.status}
        .problem=${this.keeper.problem}
        .copyTitle=${this.assignment.title}
        @shelf-request=${(event: CustomEvent<ShelfRequest>) => void this.shelfRequest(event.detail)}
      ></rt-teacher-shelf>
    </section>`;
  }

  private renderTitle() {
    return html`<section>
      <label class="field">
        ${msg('Title (the students see it)')}
        <input type="text" name="title" maxlength=${TITLE_MAX} .value=${this.assignment.title} @input=${(e: Event) => this.change({ title: (e.target as HTMLInputElement).value })} />
      </label>
    </section>`;
  }

  private renderLevels() {
    const a = this.assignment;
    const locale = a.locale;
    const available = this.levels.filter((level) => !a.levels.includes(level.id));
    const adding = available.find((level) => level.id === this.adding) ?? available[0];
    const addingIdea = adding ? this.idea(adding.id, locale) : null;
    return html`<section aria-labelledby="levels-heading">
      <h2 id="levels-heading">${msg('Levels, in the order the students play them')}</h2>
      ${
        this.guide.presets.length === 0
          ? nothing
          : html`<div class="row">
            ${msg('Start from a ready-made list:')}
            ${this.guide.presets.map(
              (preset) =>
                html`<button type="button" data-preset=${preset.id} title=${msg('Replaces the levels below with this list, each with its mandatory tasks')} @click=${() => this.usePreset(preset)}>
                  ${localize(preset.title, locale)}
                </button>`,
            )}
          </div>`
      }
      ${a.levels.length === 0 ? html`<p class="problem">${msg('Add at least one level.')}</p>` : nothing}
      <ol>
        ${a.levels.map((id, index) =>
          levelItem(
            {
              id,
              level: this.level(id),
              index,
              last: a.levels.length - 1,
              locale,
              idea: this.idea(id, locale),
              required: a.requiredTasks[id] ?? [],
              measured: this.measured.levels[id],
            },
            {
              move: (at, by) => this.moveLevel(at, by),
              remove: (level) => this.removeLevel(level),
              toggleTask: (level, task, on) => this.toggleTask(level, task, on),
            },
          ),
        )}
      </ol>
      ${a.levels.length === 0 ? nothing : html`<p class="muted" id="total-minutes">${totalMinutesText(a, this.levels, this.measured.levels)}</p>`}
      <div class="row">
        <label for="add-level">${msg('Add a level')}</label>
        <select id="add-level" name="add-level" aria-describedby="add-level-idea" ?disabled=${available.length === 0} @change=${(e: Event) => (this.adding = (e.target as HTMLSelectElement).value)}>
          ${available.map((level) => html`<option value=${level.id}>${plainLevelText(level.title, locale)}</option>`)}
        </select>
        <button
          type="button"
          ?disabled=${available.length === 0}
          title=${msg('Add the chosen level at the end of the list')}
          @click=${() => this.addLevel(this.renderRoot.querySelector<HTMLSelectElement>('#add-level')?.value ?? '')}
        >
          ${msg('Add')}
        </button>
      </div>
      <p class="idea" id="add-level-idea" data-level=${adding?.id ?? ''}>${addingIdea ?? ''}</p>
    </section>`;
  }

  private renderLink() {
    return html`<section aria-labelledby="result-heading">
      <h2 id="result-heading">${msg('Link for the students')}</h2>
      ${
        this.problem
          ? html`<p class="problem" role="alert">${this.problem}</p>`
          : html`
            <input class="link" type="text" readonly aria-label=${msg('Assignment link')} .value=${this.url ?? ''} @focus=${(e: Event) => (e.target as HTMLInputElement).select()} />
            <div class="row" style="margin-top: 8px">
              <button class="primary" type="button" ?disabled=${!this.url || this.stale} @click=${this.copy}>${msg('Copy link')}</button>
              <a class="button" href=${(!this.stale && this.url) || '#/teacher'} aria-disabled=${this.stale ? 'true' : 'false'} target="_blank" rel="noopener">${msg('Open as a student')}</a>
              <span role="status">${this.status}</span>
            </div>
            ${this.qr ? html`<img class="qr" src=${this.qr} alt=${msg('QR code of the assignment link')} />` : nothing}
            <p class="muted">${msg("Show the QR code on the projector; students scan it or type the link. Progress stays in each student's browser.")}</p>
            <rt-scorm-download .link=${this.stale ? null : this.url} .assignmentTitle=${this.assignment.title.trim()}></rt-scorm-download>
            <p><a href=${this.url ? teacherLinkHash(this.url.replace(/^[^#]*/, '')) : '#/teacher'}>${msg('This form, to bookmark or open in another browser')}</a></p>
          `
      }
    </section>`;
  }

  private renderHandout() {
    if (this.problem || !this.url || !this.qr) return nothing;
    return html`<section aria-labelledby="handout-heading">
      <h2 id="handout-heading">${msg('Handout')}</h2>
      <rt-teacher-handout .url=${this.url} .qr=${this.qr} .heading=${this.assignment.title} .classCode=${this.assignment.classCode} .askCodes=${this.assignment.askParticipantCode}></rt-teacher-handout>
    </section>`;
  }
}

customElements.define('rt-teacher-page', RtTeacherPage);

declare global {
  interface HTMLElementTagNameMap {
    'rt-teacher-page': RtTeacherPage;
  }
}
