import { msg } from '@lit/localize';
import { css, html, nothing } from 'lit';
import { LocalizedElement } from '../controls/localized-element.ts';
import { PARTICIPANT_CODE } from '../../classroom/learner-identity.ts';
import { normalParticipantCode } from '../../classroom/participant-code.ts';
import { fire, gameStyles } from './game-styles.ts';

/**
 * @summary Asks for the participant code a research study hands out, before the first
 * level of an assignment. Friendly, one field, checked as typed. With a `consent` text
 * (consent-text.ts) the pupil first reads it and presses "I understand, start"; the code
 * comes after, so that nobody types an identifier before knowing what it is for.
 *
 * @fires participant-code - CustomEvent<string>: the code, trimmed and in capitals (participant-code.ts).
 */
export class RtParticipantDialog extends LocalizedElement {
  static override properties = { heading: {}, note: {}, consent: {}, problem: { state: true }, informed: { state: true } };
  static override styles = [
    gameStyles,
    css`
      dialog {
        max-width: 420px;
        border: 1px solid var(--rt-border);
        border-radius: var(--rt-radius);
        background: var(--rt-surface);
        color: var(--rt-text);
        box-shadow: var(--rt-shadow);
      }
      label {
        display: grid;
        gap: 4px;
        margin-bottom: 8px;
      }
      .problem,
      .note {
        color: var(--rt-danger);
      }
      .actions {
        display: flex;
        justify-content: flex-end;
      }
      .consent p {
        white-space: pre-line;
      }
    `,
  ];

  /** The assignment's title. */
  declare heading: string;
  /** Why the code is asked again (a damaged saved record), or ''. */
  declare note: string;
  /** What the pupil reads before giving the code, or '' for none. */
  declare consent: string;
  declare private problem: string;
  /** The pupil has read the consent text and chose to start. */
  declare private informed: boolean;

  constructor() {
    super();
    this.heading = '';
    this.note = '';
    this.problem = '';
    this.consent = '';
    this.informed = false;
  }

  override firstUpdated(): void {
    this.renderRoot.querySelector('dialog')?.showModal();
  }

  override render() {
    return html`<dialog aria-labelledby="code-title" aria-describedby=${this.note ? 'code-note' : nothing} @cancel=${(event: Event) => event.preventDefault()}>
      ${this.consent && !this.informed ? this.renderConsent() : this.renderCode()}
    </dialog>`;
  }

  private renderConsent() {
    return html`<div class="consent">
      <h2 id="code-title">${this.heading || msg('Welcome!')}</h2>
      <h3>${msg('Before you start')}</h3>
      ${this.consent.split(/\n\s*\n/).map((paragraph) => html`<p>${paragraph.trim()}</p>`)}
      <div class="actions"><button class="primary" type="button" autofocus @click=${this.start}>${msg('I understand, start')}</button></div>
    </div>`;
  }

  private async start(): Promise<void> {
    this.informed = true;
    await this.updateComplete;
    this.renderRoot.querySelector<HTMLInputElement>('input[name=code]')?.focus();
  }

  private renderCode() {
    return html`<form @submit=${this.submit}>
        <h2 id="code-title">${this.heading || msg('Welcome!')}</h2>
        ${this.note ? html`<p id="code-note" class="note">⚠ ${this.note}</p>` : nothing}
        <p>${msg('Your teacher gave you a participant code. Type it here, so your work can be matched to you without your name.')}</p>
        <label>
          ${msg('Participant code')}
          <input type="text" name="code" autocomplete="off" required maxlength="32" aria-describedby="code-problem" />
        </label>
        <p id="code-problem" class="problem" role="alert">${this.problem}</p>
        <div class="actions"><button class="primary" type="submit">${msg('Start')}</button></div>
      </form>`;
  }

  private submit(event: Event): void {
    event.preventDefault();
    // In capitals, as handed out: `5h2-03` typed is the same learner as `5H2-03`.
    const code = normalParticipantCode(this.renderRoot.querySelector<HTMLInputElement>('input[name=code]')?.value ?? '');
    if (!PARTICIPANT_CODE.test(code)) {
      this.problem = msg('Use letters, digits, - or _ (up to 32), as on the code you were given.');
      return;
    }
    this.renderRoot.querySelector('dialog')?.close();
    fire(this, 'participant-code', code);
  }
}

customElements.define('rt-participant-dialog', RtParticipantDialog);

declare global {
  interface HTMLElementTagNameMap {
    'rt-participant-dialog': RtParticipantDialog;
  }
}
