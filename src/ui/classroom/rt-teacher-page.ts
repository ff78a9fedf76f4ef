import { msg, str } from '@lit/localize';
import { html, LitElement, nothing } from 'lit';
import QRCode from 'qrcode';
import { loadBrowserCatalog, loadBrowserLevelGuide } from '../../app/level-catalog-browser.ts';
import type { Assignment } from '../../classroom/assignment.ts';
import { assignmentSchema, CLASS_CODE, TITLE_MAX } from '../../classroom/assignment-schema.ts';
import { compactAssignment } from '../../classroom/assignment-compact.ts';
import { mandatoryTasks, withPreset } from '../../classroom/assignment-preset.ts';
import { assignmentUrl } from '../../classroom/assignment-link.ts';
import { SURVEY_IDS } from '../../classroom/surveys.ts';
import type { Level } from '../../quest/level-schema.ts';
import { playableLevels, type LevelPreset } from '../../quest/level-index.ts';
import { currentLocale } from '../../i18n/locale.ts';
import { plainLevelText } from '../../quest/text-markup.ts';
import { localize } from '../../quest/localized-text.ts';
import { teacherPageStyles } from './teacher-page.css.ts';
import '../controls/rt-theme-toggle.ts';
import './rt-teacher-concept-test.ts';

/**
 * @summary The teacher page (`#/teacher`): builds an assignment — title, levels and their
 * order (by hand or from a preset of levels/index.json, each level with its one idea),
 * required tasks, other levels, language, participant code, closing survey — and shows its
 * link with a copy button, a QR code for the projector and a link to try it as a student.
 * Nothing is stored or sent: the link is the assignment.
 */
export class RtTeacherPage extends LitElement {
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
  private made = 0;

  constructor() {
    super();
    const first = this.levels[0];
    this.assignment = {
      version: 1,
      title: msg('Ray tracing lesson'),
      levels: first ? [first.id] : [],
      requiredTasks: first ? { [first.id]: mandatoryTasks(first) } : {},
      otherLevels: 'hidden',
      // The teacher's own language: a Dutch teacher's pupils get Dutch unless chosen otherwise.
      locale: currentLocale(),
      askParticipantCode: false,
      survey: null,
    };
    this.url = null;
    this.qr = null;
    this.status = '';
    this.stale = false;
    this.adding = '';
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
    if (this.assignment.title.trim() === '') return msg('Give the assignment a title.');
    if (this.assignment.levels.length === 0) return msg('Add at least one level.');
    const { classCode, xapiHomePage } = this.assignment;
    if (classCode !== undefined && !CLASS_CODE.test(classCode)) return msg('A class code has up to 32 letters, digits, - or _ (no spaces).');
    if (xapiHomePage !== undefined && !assignmentSchema.shape.xapiHomePage.safeParse(xapiHomePage).success) {
      return msg("The school's address for xAPI must be a web address starting with https:// or http://.");
    }
    return null;
  }

  private async makeLink(): Promise<void> {
    const run = ++this.made;
    // Until the new link is made, the one shown is out of date: it must not be copied or opened.
    this.stale = true;
    if (this.problem) {
      this.url = this.qr = null;
      return;
    }
    const assignment = compactAssignment({ ...this.assignment, title: this.assignment.title.trim() }, this.levels);
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

  private change(changes: Partial<Assignment>): void {
    const next: Assignment = { ...this.assignment, ...changes };
    // An optional field left empty is left out, so the link (and the assignment's id) stays as without it.
    if (next.classCode === undefined) delete next.classCode;
    if (next.xapiHomePage === undefined) delete next.xapiHomePage;
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
    const a = this.assignment;
    const locale = a.locale;
    const available = this.levels.filter((level) => !a.levels.includes(level.id));
    const adding = available.find((level) => level.id === this.adding) ?? available[0];
    const addingIdea = adding ? this.idea(adding.id, locale) : null;
    return html`
      <header>
        <h1>${msg('Make an assignment')}</h1>
        <a class="button" href="#/">${msg('Back to the game')}</a>
        <rt-theme-toggle></rt-theme-toggle>
      </header>
      <main>
        <div>
          <section>
            <label class="field">
              ${msg('Title (the students see it)')}
              <input type="text" name="title" maxlength=${TITLE_MAX} .value=${a.title} @input=${(e: Event) => this.change({ title: (e.target as HTMLInputElement).value })} />
            </label>
          </section>
          <section aria-labelledby="levels-heading">
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
              ${a.levels.map((id, index) => this.renderLevel(id, index, locale))}
            </ol>
            <div class="row">
              <label for="add-level">${msg('Add a level')}</label>
              <select
                id="add-level"
                name="add-level"
                aria-describedby="add-level-idea"
                ?disabled=${available.length === 0}
                @change=${(e: Event) => (this.adding = (e.target as HTMLSelectElement).value)}
              >
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
          </section>
          <section>
            <h2>${msg('Settings')}</h2>
            ${this.renderChoice(msg('Other levels'), 'otherLevels', a.otherLevels, [
              ['hidden', msg('Hidden: only the assignment')],
              ['shown', msg('Shown: playable after the assignment')],
            ])}
            ${this.renderChoice(msg('Language'), 'locale', a.locale, [
              ['en', 'English'],
              ['nl', 'Nederlands'],
            ])}
            ${this.renderChoice(msg('Participant code'), 'askParticipantCode', a.askParticipantCode ? 'yes' : 'no', [
              ['no', msg('Do not ask')],
              ['yes', msg('Ask for a code at the start (for research)')],
            ])}
            ${this.renderChoice(msg('Closing survey'), 'survey', a.survey ?? 'none', [
              ['none', msg('None')],
              ...SURVEY_IDS.map((id): [string, string] => [id, id === 'default' ? msg('The standard questions (about 5 minutes)') : id]),
            ])}
            ${a.survey ? html`<a href=${`#/survey/${a.survey}`} target="_blank" rel="noopener">${msg('Preview the survey (opens a new tab)')}</a>` : nothing}
          </section>
          <rt-teacher-concept-test .value=${a.conceptTest} @concept-test-change=${(e: CustomEvent<Assignment['conceptTest']>) => this.change({ conceptTest: e.detail })}></rt-teacher-concept-test>
          <section>
            <h2>${msg('For the dashboard and research (optional)')}</h2>
            <label class="field">
              ${msg('Class code (the dashboard can show one class)')}
              <input type="text" name="class-code" maxlength="32" placeholder="3B" .value=${a.classCode ?? ''} @input=${(e: Event) => this.change({ classCode: optional((e.target as HTMLInputElement).value) })} />
            </label>
            <label class="field">
              ${msg("Your school's web address, for xAPI accounts")}
              <input
                type="url"
                name="xapi-home-page"
                maxlength="200"
                placeholder="https://school.example"
                .value=${a.xapiHomePage ?? ''}
                @input=${(e: Event) => this.change({ xapiHomePage: optional((e.target as HTMLInputElement).value) })}
              />
            </label>
            <p class="muted">${msg('With a learning record store shared by schools, this keeps code "P-07" of your school apart from another school\'s.')}</p>
          </section>
        </div>
        <section class="result" aria-labelledby="result-heading">
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
              `
          }
        </section>
      </main>
    `;
  }

  private renderLevel(id: string, index: number, locale: Assignment['locale']) {
    const level = this.level(id);
    const title = level ? plainLevelText(level.title, locale) : id;
    const idea = this.idea(id, locale);
    const required = new Set(this.assignment.requiredTasks[id] ?? []);
    const last = this.assignment.levels.length - 1;
    return html`<li data-level=${id}>
      <div class="level-head">
        <span class="level-name"><strong>${title}</strong>${idea === null ? nothing : html`<span class="idea">${idea}</span>`}</span>
        <button class="icon" type="button" data-move="-1" ?disabled=${index === 0} aria-label=${msg(str`Move ${title} up`)} title=${msg('Move up')} @click=${() => this.moveLevel(index, -1)}>↑</button>
        <button class="icon" type="button" data-move="1" ?disabled=${index === last} aria-label=${msg(str`Move ${title} down`)} title=${msg('Move down')} @click=${() => this.moveLevel(index, 1)}>↓</button>
        <button class="icon" type="button" aria-label=${msg(str`Remove ${title}`)} title=${msg('Remove from the assignment')} @click=${() => this.removeLevel(id)}>✕</button>
      </div>
      ${
        level
          ? html`<fieldset>
            <legend>${msg('Required tasks (the others are optional)')}</legend>
            ${level.tasks.map(
              (task) => html`<label class="check">
                <input type="checkbox" name=${`${id}/${task.id}`} .checked=${required.has(task.id)} @change=${(e: Event) => this.toggleTask(id, task.id, (e.target as HTMLInputElement).checked)} />
                ${plainLevelText(task.title, locale)} ${task.mandatory ? nothing : html`<span class="muted">${msg('(optional in the level)')}</span>`}
              </label>`,
            )}
          </fieldset>`
          : nothing
      }
    </li>`;
  }

  private renderChoice(legend: string, name: 'otherLevels' | 'locale' | 'askParticipantCode' | 'survey', value: string, options: [string, string][]) {
    const pick = (option: string) => {
      if (name === 'askParticipantCode') this.change({ askParticipantCode: option === 'yes' });
      else if (name === 'survey') this.change({ survey: option === 'none' ? null : option });
      else if (name === 'locale') this.change({ locale: option === 'nl' ? 'nl' : 'en' });
      else this.change({ otherLevels: option === 'shown' ? 'shown' : 'hidden' });
    };
    return html`<fieldset class="choices">
      <legend>${legend}</legend>
      ${options.map(
        ([option, label]) => html`<label class="check">
          <input type="radio" name=${name} value=${option} .checked=${value === option} @change=${() => pick(option)} />
          ${label}
        </label>`,
      )}
    </fieldset>`;
  }
}

/** A typed optional field: trimmed, undefined when empty. */
function optional(text: string): string | undefined {
  return text.trim() === '' ? undefined : text.trim();
}

customElements.define('rt-teacher-page', RtTeacherPage);

declare global {
  interface HTMLElementTagNameMap {
    'rt-teacher-page': RtTeacherPage;
  }
}
