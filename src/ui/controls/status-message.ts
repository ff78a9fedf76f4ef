import { html, nothing, type ReactiveController, type ReactiveControllerHost, type TemplateResult } from 'lit';
import { ifDefined } from 'lit/directives/if-defined.js';

// Drawn rather than typed: not every school computer's fonts have ⓘ and ⚠.
const INFO = html`<svg class="message-icon" viewBox="0 0 16 16" width="14" height="14" aria-hidden="true">
  <circle cx="8" cy="8" r="7" fill="none" stroke="currentColor" stroke-width="1.5" />
  <path d="M8 7v5M8 4.2v.1" stroke="currentColor" stroke-width="1.8" stroke-linecap="round" />
</svg>`;
const WARNING = html`<svg class="message-icon" viewBox="0 0 16 16" width="14" height="14" aria-hidden="true">
  <path d="M8 1.5 15 14.5H1Z" fill="none" stroke="currentColor" stroke-width="1.5" stroke-linejoin="round" />
  <path d="M8 6v4.5M8 12.6v.1" stroke="currentColor" stroke-width="1.8" stroke-linecap="round" />
</svg>`;

/** How long a note about typed input stays (long enough to read twice, short enough not to linger). */
const SHOW_MS = 5000;

/**
 * The message line next to a control: a passing note about what was typed ("Clamped to
 * 1–170" as info, "Type a number…" as a problem) or else the store's reason for refusing a
 * change, which stays until the host's `error` is cleared. One live region (role="status")
 * per control, always present so that screen readers announce what appears in it; an
 * icon as well as a colour tells info from problem.
 */
export class StatusMessage implements ReactiveController {
  private text = '';
  private problem = false;
  private timer: ReturnType<typeof setTimeout> | undefined;

  constructor(private readonly host: ReactiveControllerHost) {
    host.addController(this);
  }

  /** Shows `text` for a few seconds (nothing when undefined); `problem` for input that was not taken. */
  show(text: string | undefined, problem = false): void {
    clearTimeout(this.timer);
    this.text = text ?? '';
    this.problem = problem;
    if (text) {
      this.timer = setTimeout(() => {
        this.text = '';
        this.host.requestUpdate();
      }, SHOW_MS);
    }
    this.host.requestUpdate();
  }

  hostDisconnected(): void {
    clearTimeout(this.timer);
    this.text = '';
  }

  /** The message line, with id "message" for aria-describedby; `error` is the store's refusal. */
  render(error: string | undefined): TemplateResult {
    return this.text ? messageLine(this.text, this.problem, 'message') : messageLine(error, true, 'message');
  }
}

/** A message line (role="status"): empty when `text` is, a problem drawn with ⚠, info with ⓘ. */
export function messageLine(text: string | undefined, problem: boolean, id?: string): TemplateResult {
  return html`<p id=${ifDefined(id)} class=${problem ? 'message problem' : 'message'} role="status">${text ? html`${problem ? WARNING : INFO} ${text}` : nothing}</p>`;
}
