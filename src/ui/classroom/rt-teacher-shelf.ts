import { msg, str } from '@lit/localize';
import { css, html, nothing } from 'lit';
import type { SavedAssignment } from '../../classroom/saved-assignments.ts';
import { CLASS_CODE, TITLE_MAX } from '../../classroom/assignment-schema.ts';
import { formatLocale } from '../../i18n/format-locale.ts';
import { classroomStyles } from './classroom-styles.ts';
import { LocalizedElement } from '../controls/localized-element.ts';

/** What the page is asked to do with the kept assignments. */
export type ShelfRequest =
  | { kind: 'open'; id: string }
  | { kind: 'remove'; id: string }
  | { kind: 'new' }
  | { kind: 'open-link'; link: string }
  | { kind: 'copy'; title: string; classCode: string };

/**
 * @summary The teacher's assignments kept in this browser (classroom/saved-assignments.ts):
 * each with its class and when it was last changed (local time), to open again or forget;
 * a new one; one opened from its link; and a copy of the open one for another class (same
 * levels and settings, its own title and class code). It shows what the page keeps; the
 * page does the keeping and says whether it worked (`status`).
 *
 * @fires shelf-request - CustomEvent<ShelfRequest>.
 */
export class RtTeacherShelf extends LocalizedElement {
  static override properties = {
    entries: { attribute: false },
    current: {},
    status: {},
    problem: { type: Boolean },
    copyTitle: { attribute: false },
    copying: { state: true },
  };

  static override styles = [
    classroomStyles,
    css`
      ul {
        list-style: none;
        margin: 0 0 var(--rt-space);
        padding: 0;
        max-height: 13.5em;
        overflow-y: auto;
      }
      li {
        display: flex;
        align-items: center;
        gap: 6px;
        padding: 2px 4px;
        border-radius: 6px;
      }
      li[aria-current='true'] {
        background: var(--rt-accent-soft);
      }
      .name {
        flex: 1;
        min-width: 0;
      }
      .row {
        display: flex;
        flex-wrap: wrap;
        gap: var(--rt-space);
        align-items: end;
        margin-top: 6px;
      }
      label {
        display: grid;
        gap: 2px;
        font-size: 0.9em;
      }
      .grow {
        flex: 1;
        min-width: 12em;
      }
      .icon {
        min-width: var(--rt-target);
        justify-content: center;
        padding: 4px;
      }
    `,
  ];

  declare entries: SavedAssignment[];
  /** The id of the assignment the form shows. */
  declare current: string;
  /** Whether the open assignment is kept, or why not. */
  declare status: string;
  /** The status tells of a failure. */
  declare problem: boolean;
  /** The open assignment's title: the copy's starting title. */
  declare copyTitle: string;
  /** The copy form is open. */
  declare copying: boolean;

  constructor() {
    super();
    this.entries = [];
    this.current = '';
    this.status = '';
    this.problem = false;
    this.copyTitle = '';
    this.copying = false;
  }

  override render() {
    // Local time, in the page's language: "7 dec. 2026 09:05" for a Dutch teacher.
    const when = new Intl.DateTimeFormat(formatLocale(), { dateStyle: 'medium', timeStyle: 'short' });
    return html`
      <p class=${this.problem ? 'problem' : 'muted'} role="status">${this.status}</p>
      ${
        this.entries.length === 0
          ? nothing
          : html`<ul aria-label=${msg('Kept assignments')}>
            ${this.entries.map(
              (entry) => html`<li aria-current=${entry.id === this.current ? 'true' : 'false'} data-entry=${entry.id}>
                <span class="name"
                  ><strong>${entry.assignment.title}</strong>${entry.assignment.classCode ? ` · ${entry.assignment.classCode}` : ''}
                  <span class="muted">· ${when.format(new Date(entry.savedAt))}</span></span
                >
                ${entry.id === this.current ? html`<span class="muted">${msg('(open)')}</span>` : html`<button type="button" @click=${() => this.ask({ kind: 'open', id: entry.id })}>${msg('Open')}</button>`}
                <button
                  class="icon"
                  type="button"
                  aria-label=${msg(str`Forget ${entry.assignment.title}`)}
                  title=${msg('Forget it in this browser (its link keeps working)')}
                  @click=${() => this.forget(entry)}
                >
                  ✕
                </button>
              </li>`,
            )}
          </ul>`
      }
      <div class="row">
        <button type="button" @click=${() => this.ask({ kind: 'new' })}>${msg('New assignment')}</button>
        <button type="button" aria-expanded=${this.copying ? 'true' : 'false'} @click=${() => (this.copying = !this.copying)}>${msg('Copy for another class…')}</button>
      </div>
      ${this.copying ? this.renderCopy() : nothing}
      <form class="row" @submit=${this.openLink}>
        <label class="grow">
          ${msg('Open an assignment from its link')}
          <input type="text" inputmode="url" name="link" placeholder="https://…#/a/1…" />
        </label>
        <button type="submit">${msg('Open link')}</button>
      </form>
    `;
  }

  private renderCopy() {
    return html`<form class="row" @submit=${this.copy}>
      <label class="grow">
        ${msg('Title of the copy')}
        <input type="text" name="copy-title" required maxlength=${TITLE_MAX} .value=${this.copyTitle} />
      </label>
      <label>
        ${msg('Class code')}
        <input type="text" name="copy-class" maxlength="32" placeholder="5H3" pattern=${CLASS_CODE.source} />
      </label>
      <button class="primary" type="submit">${msg('Make the copy')}</button>
    </form>`;
  }

  private forget(entry: SavedAssignment): void {
    if (confirm(msg(str`Forget "${entry.assignment.title}" in this browser? Its link keeps working; you can open it again from the link.`))) {
      this.ask({ kind: 'remove', id: entry.id });
    }
  }

  private copy(event: Event): void {
    event.preventDefault();
    const form = event.target as HTMLFormElement;
    const field = (name: string) => form.querySelector<HTMLInputElement>(`[name=${name}]`)?.value.trim() ?? '';
    this.ask({ kind: 'copy', title: field('copy-title'), classCode: field('copy-class') });
    this.copying = false;
  }

  private openLink(event: Event): void {
    event.preventDefault();
    const field = (event.target as HTMLFormElement).querySelector<HTMLInputElement>('[name=link]');
    if (field && field.value.trim() !== '') this.ask({ kind: 'open-link', link: field.value.trim() });
  }

  private ask(request: ShelfRequest): void {
    this.dispatchEvent(new CustomEvent<ShelfRequest>('shelf-request', { detail: request, bubbles: true, composed: true }));
  }
}

customElements.define('rt-teacher-shelf', RtTeacherShelf);

declare global {
  interface HTMLElementTagNameMap {
    'rt-teacher-shelf': RtTeacherShelf;
  }
}
