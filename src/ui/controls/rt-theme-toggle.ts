import { msg } from '@lit/localize';
import { css, html } from 'lit';
import { LocalizedElement } from './localized-element.ts';
import { applyTheme, savedTheme, type ThemeChoice } from '../../app/theme.ts';

const NEXT: Record<ThemeChoice, ThemeChoice> = { system: 'light', light: 'dark', dark: 'system' };

/**
 * @summary A button that cycles the colour theme: system → light → dark, remembered.
 */
export class RtThemeToggle extends LocalizedElement {
  static override properties = { choice: { state: true } };

  static override styles = css`
    button {
      font: inherit;
      min-height: var(--rt-target);
      padding: 0 10px;
      border-radius: 8px;
      border: 1px solid var(--rt-control-border);
      background: var(--rt-surface);
      color: var(--rt-text);
      cursor: pointer;
    }
    button:focus-visible {
      outline: 3px solid var(--rt-focus);
      outline-offset: 2px;
    }
  `;

  declare choice: ThemeChoice;

  constructor() {
    super();
    this.choice = savedTheme();
  }

  override connectedCallback(): void {
    super.connectedCallback();
    applyTheme(this.choice);
  }

  private label(choice: ThemeChoice): string {
    return { system: msg('Theme: system'), light: msg('Theme: light'), dark: msg('Theme: dark') }[choice];
  }

  override render() {
    return html`<button
      @click=${() => {
        this.choice = NEXT[this.choice];
        applyTheme(this.choice);
      }}
      title=${msg('Switch between the system theme, light and dark')}
    >
      ${this.label(this.choice)}
    </button>`;
  }
}

customElements.define('rt-theme-toggle', RtThemeToggle);

declare global {
  interface HTMLElementTagNameMap {
    'rt-theme-toggle': RtThemeToggle;
  }
}
