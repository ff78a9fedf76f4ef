import { css } from 'lit';

/**
 * Buttons and toggle groups shared by the render window and its image viewer: 32 px targets
 * (touch tablets), visible focus, and pressed/checked states shown by fill and weight, not by
 * colour alone.
 */
export const controlStyles = css`
  button,
  .toggle span {
    box-sizing: border-box;
    min-height: var(--rt-target);
    min-width: var(--rt-target);
    padding: 4px 12px;
    border-radius: 8px;
    border: 1px solid var(--rt-border);
    background: var(--rt-surface);
    color: var(--rt-text);
    font: inherit;
    line-height: 1.2;
    cursor: pointer;
    display: inline-flex;
    align-items: center;
    justify-content: center;
  }
  button:hover:not(:disabled),
  .toggle span:hover {
    border-color: var(--rt-accent);
  }
  button.primary {
    background: var(--rt-accent);
    border-color: var(--rt-accent);
    color: var(--rt-accent-text);
    font-weight: 600;
  }
  button[aria-pressed='true'],
  .toggle input:checked + span {
    background: color-mix(in srgb, var(--rt-accent) 18%, var(--rt-surface));
    border-color: var(--rt-accent);
    font-weight: 600;
  }
  button:disabled {
    opacity: 0.45;
    cursor: default;
  }
  button:focus-visible,
  .toggle input:focus-visible + span,
  input[type='range']:focus-visible,
  [tabindex]:focus-visible {
    outline: 3px solid var(--rt-accent);
    outline-offset: 2px;
  }
  /* A radio button drawn as a segment of a button group; the input stays focusable. */
  .toggle {
    position: relative;
    display: inline-flex;
  }
  .toggle input {
    position: absolute;
    opacity: 0;
    width: 1px;
    height: 1px;
    margin: 0;
  }
  .group {
    display: inline-flex;
    align-items: center;
    gap: 4px;
    flex-wrap: wrap;
  }
  .group-label {
    color: var(--rt-muted);
    font-size: 0.85rem;
    margin-right: 2px;
  }
`;
