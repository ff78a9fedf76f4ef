import { css } from 'lit';

/**
 * Styles shared by the panel controls (rt-slider, rt-switch, …) and the panels. Colours
 * come only from the theme's --rt-* properties, so light and dark themes follow; spacing
 * is on an 8 px grid (4 px for the tight gaps inside a control), and every target is
 * --rt-target high: 32 px for a mouse, 44 px on a touch screen (theme.css).
 */
export const controlStyles = css`
  :host {
    display: block;
    color: var(--rt-text);
    font-family: var(--rt-font);
    font-size: 0.875rem;
    line-height: 1.3;
  }
  :host([hidden]) {
    display: none;
  }
  .row {
    display: flex;
    align-items: center;
    justify-content: space-between;
    gap: 8px;
    min-height: var(--rt-target);
  }
  .label {
    flex: 1 1 auto;
    min-width: 0;
    overflow-wrap: anywhere;
  }
  input[type='text'] {
    box-sizing: border-box;
    height: var(--rt-target);
    min-width: 0;
    padding: 0 8px;
    border: 1px solid var(--rt-control-border);
    border-radius: 6px;
    background: var(--rt-bg);
    color: var(--rt-text);
    font: inherit;
    font-variant-numeric: tabular-nums;
  }
  input:disabled,
  button:disabled {
    opacity: 0.5;
    cursor: not-allowed;
  }
  :focus-visible {
    outline: 3px solid var(--rt-accent);
    outline-offset: 2px;
  }
  .unit {
    min-width: 1ch;
    color: var(--rt-muted);
  }
  .message {
    margin: 4px 0 0;
    color: var(--rt-muted);
    font-size: 0.8125rem;
  }
  .message-icon {
    vertical-align: -2px;
  }
  .message:empty {
    margin: 0;
  }
  .message.problem {
    color: var(--rt-danger);
  }
  button {
    box-sizing: border-box;
    min-height: var(--rt-target);
    padding: 0 12px;
    border: 1px solid var(--rt-control-border);
    border-radius: 6px;
    background: var(--rt-surface);
    color: var(--rt-text);
    font: inherit;
    cursor: pointer;
  }
  button:hover:not(:disabled) {
    border-color: var(--rt-accent);
  }
  button[aria-pressed='true'] {
    border-color: var(--rt-accent);
    background: var(--rt-accent);
    color: var(--rt-accent-text);
  }
`;
