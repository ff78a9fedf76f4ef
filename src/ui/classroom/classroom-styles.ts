import { css } from 'lit';

/** The looks the classroom's pages share (teacher page, survey): buttons, fields, messages. */
export const classroomStyles = css`
  :host {
    color: var(--rt-text);
    font-family: var(--rt-font);
  }
  button,
  .button {
    font: inherit;
    min-height: var(--rt-target);
    padding: 4px 14px;
    border-radius: var(--rt-radius);
    border: 1px solid var(--rt-border);
    background: var(--rt-surface);
    color: var(--rt-text);
    cursor: pointer;
    text-decoration: none;
    display: inline-flex;
    align-items: center;
    gap: 6px;
  }
  button.primary,
  .button.primary {
    background: var(--rt-accent);
    border-color: var(--rt-accent);
    color: var(--rt-accent-text);
  }
  button:disabled {
    opacity: 0.5;
    cursor: not-allowed;
  }
  :is(button, .button, input, textarea, select, a):focus-visible {
    outline: 3px solid var(--rt-focus);
    outline-offset: 2px;
  }
  input[type='text'],
  input:not([type]),
  textarea,
  select {
    font: inherit;
    color: var(--rt-text);
    background: var(--rt-surface-2);
    border: 1px solid var(--rt-border);
    border-radius: 6px;
    padding: 6px 8px;
    min-height: var(--rt-target);
    box-sizing: border-box;
  }
  input[type='radio'],
  input[type='checkbox'] {
    width: 18px;
    height: 18px;
    accent-color: var(--rt-accent);
  }
  .problem {
    color: var(--rt-danger);
    font-weight: 600;
  }
  .problem::before {
    content: '⚠ ';
  }
  .muted {
    color: var(--rt-muted);
  }
`;

/** The frame of a classroom page (teacher page, dashboard): a header bar with the title, and card sections. */
export const pageStyles = css`
  :host {
    display: block;
    min-height: 100vh;
    background: var(--rt-bg);
  }
  header {
    display: flex;
    align-items: center;
    gap: calc(var(--rt-space) * 2);
    padding: 8px 16px;
    background: var(--rt-surface);
    border-bottom: 1px solid var(--rt-border);
  }
  header h1 {
    font-size: 1.2rem;
    margin: 0;
    flex: 1;
  }
  section {
    background: var(--rt-surface);
    border: 1px solid var(--rt-border);
    border-radius: var(--rt-radius);
    padding: 12px 16px;
  }
`;
