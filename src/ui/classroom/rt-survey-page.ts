import { msg } from '@lit/localize';
import { css, html } from 'lit';
import { LocalizedElement } from '../controls/localized-element.ts';
import type { Locale } from '../../quest/localized-text.ts';
import { FocusReturn } from '../controls/focus-return.ts';
import { classroomStyles } from './classroom-styles.ts';
import type { Assignment } from '../../classroom/assignment.ts';
import './rt-survey.ts';

/**
 * @summary The closing survey on a page of its own, laid over the lab once an assignment is
 * passed: its questions in a readable column (at most 760 px, so a question reads as lines of
 * words and a 1–10 scale as one row), instead of the lab's narrow task column. "Later" (or
 * Esc) goes back to the lab; the task column then offers the survey again.
 *
 * The survey's own `survey-submitted` event bubbles out of this element unchanged.
 * @fires survey-later - the learner goes back to the lab without handing in.
 */
export class RtSurveyPage extends LocalizedElement {
  static override properties = { surveyId: { attribute: 'survey-id' }, locale: {}, levels: { attribute: false }, choice: { attribute: false } };

  static override styles = [
    classroomStyles,
    css`
      :host {
        display: block;
        overflow-y: auto;
        padding: 8px 16px 24px;
        background: var(--rt-bg);
      }
      section {
        max-width: 760px;
        margin: 0 auto;
      }
      section:focus {
        outline: none;
      }
      .bar {
        display: flex;
        justify-content: flex-end;
        padding: 0 16px;
      }
      rt-survey {
        padding-top: 0;
      }
      /* A phone: the survey's own margin is enough. */
      @media (max-width: 559px) {
        :host {
          padding: 8px 0 24px;
        }
      }
    `,
  ];

  declare surveyId: string;
  declare locale: Locale;
  /** The assignment's levels (rt-survey.ts). */
  declare levels: readonly string[] | null;
  /** The teacher's own choice of questions (rt-survey.ts). */
  declare choice: Assignment['surveyQuestions'];
  private readonly focusReturn = new FocusReturn();

  constructor() {
    super();
    this.surveyId = 'default';
    this.locale = 'en';
    this.levels = null;
    this.addEventListener('keydown', (event) => {
      if (event.key === 'Escape') this.later();
    });
  }

  override connectedCallback(): void {
    super.connectedCallback();
    this.focusReturn.remember();
  }

  override disconnectedCallback(): void {
    super.disconnectedCallback();
    this.focusReturn.restore(this);
  }

  /** The page covers the lab: the focus comes onto it (read out by its name), not left behind it. */
  protected override firstUpdated(): void {
    this.renderRoot.querySelector<HTMLElement>('section')?.focus();
  }

  private later(): void {
    this.dispatchEvent(new CustomEvent('survey-later', { bubbles: true, composed: true }));
  }

  override render() {
    return html`<section tabindex="-1" aria-label=${msg('Closing survey')}>
      <div class="bar">
        <button @click=${this.later} title=${msg('Back to the lab; the survey waits in the task column (Esc)')}>${msg('Later')}</button>
      </div>
      <rt-survey survey-id=${this.surveyId} locale=${this.locale} .levels=${this.levels} .choice=${this.choice}></rt-survey>
    </section>`;
  }
}

customElements.define('rt-survey-page', RtSurveyPage);

declare global {
  interface HTMLElementTagNameMap {
    'rt-survey-page': RtSurveyPage;
  }
}
