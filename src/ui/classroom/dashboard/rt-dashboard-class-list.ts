import { msg, str } from '@lit/localize';
import { css, html, nothing } from 'lit';
import { checkClassList, parseClassList, type ClassListCheck } from '../../../classroom/dashboard-class-list.ts';
import type { ClassLearner } from '../../../classroom/dashboard-learners.ts';
import { classroomStyles } from '../classroom-styles.ts';
import { codeBoxStyles } from '../code-box.css.ts';
import { LocalizedElement } from '../../controls/localized-element.ts';

/** Where the pasted list is kept, so that a reload or the next lesson does not ask for it again. */
export const CLASS_LIST_KEY = 'rtq.dashboard.class-list';

/**
 * @summary The class list: the teacher pastes the participant codes they handed out (one
 * per line) and sees who has handed in, who is missing, and whose results carry a code that
 * is not on the list, with their files. Set `.learners` (the learners shown). The list stays
 * in this browser only (localStorage).
 */
export class RtDashboardClassList extends LocalizedElement {
  static override properties = {
    learners: { attribute: false },
    text: { state: true },
  };

  static override styles = [
    classroomStyles,
    codeBoxStyles,
    css`
      :host {
        display: block;
        --code-box-height: 12em;
      }
      .paste {
        display: grid;
        grid-template-columns: minmax(12em, 18em) 1fr;
        gap: calc(var(--rt-space) * 2);
        align-items: start;
      }
      .summary {
        margin: 0 0 var(--rt-space);
        font-weight: 600;
      }
      .lists {
        display: grid;
        grid-template-columns: repeat(auto-fit, minmax(14em, 1fr));
        gap: calc(var(--rt-space) * 2);
      }
      h3 {
        font-size: 1rem;
        margin: 0 0 4px;
      }
      ul {
        margin: 0;
        padding-left: 1.2em;
        overflow-wrap: anywhere;
      }
      .files {
        color: var(--rt-muted);
        font-size: 0.9em;
      }
      .missing h3 {
        color: var(--rt-danger, var(--rt-text));
      }
      @media (max-width: 700px) {
        .paste {
          grid-template-columns: 1fr;
        }
      }
    `,
  ];

  declare learners: readonly ClassLearner[];
  declare text: string;

  constructor() {
    super();
    this.learners = [];
    this.text = readSaved();
  }

  private onInput(event: Event): void {
    this.text = (event.target as HTMLTextAreaElement).value;
    try {
      localStorage.setItem(CLASS_LIST_KEY, this.text);
    } catch {
      // Blocked storage: the list holds for this visit.
    }
  }

  override render() {
    const codes = parseClassList(this.text);
    return html`<div class="paste">
      <label>
        ${msg('Participant codes you handed out, one per line')}
        <textarea .value=${this.text} @input=${this.onInput} spellcheck="false" placeholder=${'5H2-01\n5H2-02\n5H2-03'}></textarea>
      </label>
      <div>${codes.length === 0 ? html`<p>${msg('Paste the class list to see who has handed in and who is missing. Upper and lower case do not matter.')}</p>` : this.renderCheck(codes.length, checkClassList(codes, this.learners))}</div>
    </div>`;
  }

  private renderCheck(listed: number, check: ClassListCheck) {
    const files = (learner: ClassLearner) => html`<span class="files">(${learner.files.join(', ')})</span>`;
    return html`<p class="summary" aria-live="polite">
        ${msg(str`${check.handedIn.length} of ${listed} handed in, ${check.missing.length} missing.`)}
        ${check.notOnList.length === 0 ? nothing : msg(str`Not on the list: ${check.notOnList.length}.`)}
      </p>
      <div class="lists">
        <div class="missing">
          <h3>${msg(str`Missing (${check.missing.length})`)}</h3>
          <ul>
            ${check.missing.map((code) => html`<li>${code}</li>`)}
          </ul>
        </div>
        <div class="handed-in">
          <h3>${msg(str`Handed in (${check.handedIn.length})`)}</h3>
          <ul>
            ${check.handedIn.map(({ code, learners }) => html`<li>${code} ${learners.map(files)}</li>`)}
          </ul>
        </div>
        ${
          check.notOnList.length === 0
            ? nothing
            : html`<div class="not-on-list">
              <h3>${msg(str`Not on the list (${check.notOnList.length})`)}</h3>
              <ul>
                ${check.notOnList.map((learner) => html`<li>${learner.participant || msg('(no code)')} ${files(learner)}</li>`)}
              </ul>
            </div>`
        }
      </div>`;
  }
}

function readSaved(): string {
  try {
    return localStorage.getItem(CLASS_LIST_KEY) ?? '';
  } catch {
    return '';
  }
}

customElements.define('rt-dashboard-class-list', RtDashboardClassList);

declare global {
  interface HTMLElementTagNameMap {
    'rt-dashboard-class-list': RtDashboardClassList;
  }
}
