import { css } from 'lit';
import { classroomStyles, pageStyles } from '../classroom-styles.ts';

/** The dashboard page's layout: the drop zone, the filters, each level's charts and tables, the survey charts. */
export const dashboardPageStyles = [
  classroomStyles,
  pageStyles,
  css`
      main {
        display: flex;
        flex-direction: column;
        gap: calc(var(--rt-space) * 2);
        padding: calc(var(--rt-space) * 2);
        max-width: 1200px;
        margin: 0 auto;
      }
      h2 {
        font-size: 1.1rem;
        margin: 0 0 var(--rt-space);
      }
      h3 {
        font-size: 1rem;
        margin: calc(var(--rt-space) * 2) 0 var(--rt-space);
      }
      .drop {
        border: 2px dashed var(--rt-border);
        border-radius: var(--rt-radius);
        padding: 20px;
        display: flex;
        flex-wrap: wrap;
        align-items: center;
        gap: var(--rt-space) calc(var(--rt-space) * 2);
      }
      .drop.dragging {
        border-color: var(--rt-accent);
        border-style: solid;
        background: var(--rt-accent-soft);
      }
      .drop p {
        margin: 0;
        flex: 1 1 20em;
      }
      .privacy {
        display: flex;
        gap: 6px;
        align-items: center;
        margin: var(--rt-space) 0 0;
        color: var(--rt-muted);
      }
      .actions {
        display: flex;
        flex-wrap: wrap;
        gap: var(--rt-space);
        align-items: center;
        margin-top: var(--rt-space);
      }
      /* The file input is reached by Tab inside its label, which shows the focus. */
      input[type='file'] {
        position: absolute;
        width: 1px;
        height: 1px;
        opacity: 0;
      }
      label.button {
        position: relative;
      }
      label.button:focus-within {
        outline: 3px solid var(--rt-focus);
        outline-offset: 2px;
      }
      .status {
        margin: var(--rt-space) 0 0;
        font-weight: 600;
      }
      table.skipped {
        border-collapse: collapse;
        width: 100%;
        font-size: 0.9rem;
      }
      table.skipped th,
      table.skipped td {
        text-align: left;
        padding: 4px 8px;
        border-bottom: 1px solid var(--rt-border);
        vertical-align: top;
        overflow-wrap: anywhere;
      }
      .filter {
        display: flex;
        flex-wrap: wrap;
        gap: var(--rt-space) calc(var(--rt-space) * 2);
        align-items: center;
        margin-top: var(--rt-space);
      }
      .filter label {
        display: flex;
        gap: 6px;
        align-items: center;
      }
      .rule {
        margin: 0 0 var(--rt-space);
        color: var(--rt-muted);
        max-width: 70em;
      }
      .level-facts {
        margin: 0;
        color: var(--rt-muted);
      }
    `,
];
