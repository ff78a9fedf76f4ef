import { css } from 'lit';

/**
 * The text box the classroom pastes into or copies from (the dashboard's results codes and
 * class list, the pupil's results code): full width, as high as `--code-box-height`, grown
 * by dragging, its label above it. A box of codes (`.codes`) is monospaced and breaks
 * anywhere, since a results code is one long word.
 */
export const codeBoxStyles = css`
  textarea {
    font: inherit;
    width: 100%;
    box-sizing: border-box;
    height: var(--code-box-height, 6em);
    resize: vertical;
    background: var(--rt-surface);
    color: var(--rt-text);
    border: 1px solid var(--rt-border);
    border-radius: var(--rt-radius);
  }
  textarea.codes {
    font: 0.85em / 1.3 ui-monospace, monospace;
    word-break: break-all;
  }
  label {
    display: grid;
    gap: 4px;
  }
`;
