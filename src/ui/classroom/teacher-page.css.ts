import { css } from 'lit';
import { classroomStyles, pageStyles } from './classroom-styles.ts';

/**
 * The teacher page's layout: the assignment form, the level list with its tasks, the link and
 * its QR code; in print, only the handout (rt-teacher-handout.ts draws its sheet).
 */
export const teacherPageStyles = [
  classroomStyles,
  pageStyles,
  css`
      main {
        display: grid;
        grid-template-columns: minmax(0, 1fr) minmax(300px, 420px);
        gap: calc(var(--rt-space) * 2);
        padding: calc(var(--rt-space) * 2);
        max-width: 1280px;
        margin: 0 auto;
      }
      section {
        margin-bottom: calc(var(--rt-space) * 2);
      }
      h2 {
        font-size: 1.05rem;
        margin: 0 0 var(--rt-space);
      }
      label.field {
        display: grid;
        gap: 4px;
        font-weight: 600;
      }
      label.field + label.field {
        margin-top: var(--rt-space);
      }
      ol {
        padding-left: 1.5em;
        margin: 0 0 var(--rt-space);
      }
      li {
        margin-bottom: var(--rt-space);
        padding: 8px;
        border: 1px solid var(--rt-border);
        border-radius: 6px;
        background: var(--rt-surface-2);
      }
      .level-head {
        display: flex;
        align-items: center;
        gap: 6px;
        flex-wrap: wrap;
      }
      .level-name {
        flex: 1;
        min-width: 10em;
      }
      .level-facts {
        margin: 4px 0 0;
        font-size: 0.9em;
      }
      .idea {
        display: block;
        font-size: 0.9em;
        color: var(--rt-muted);
      }
      .icon {
        min-width: var(--rt-target);
        justify-content: center;
        padding: 4px;
      }
      fieldset {
        border: 0;
        margin: 6px 0 0;
        padding: 0;
      }
      legend {
        font-size: 0.9em;
        color: var(--rt-muted);
        padding: 0;
      }
      .check {
        display: flex;
        gap: 6px;
        align-items: center;
        min-height: 28px;
        cursor: pointer;
      }
      .row {
        display: flex;
        flex-wrap: wrap;
        gap: var(--rt-space);
        align-items: center;
      }
      .choices {
        display: flex;
        flex-wrap: wrap;
        gap: 4px 16px;
        margin-bottom: var(--rt-space);
      }
      .result {
        position: sticky;
        top: calc(var(--rt-space) * 2);
        align-self: start;
        /* The handout and the dashboard follow the QR code: all of it stays reachable on a laptop screen. */
        max-height: calc(100vh - var(--rt-space) * 4);
        overflow-y: auto;
      }
      .link {
        width: 100%;
        font-family: ui-monospace, monospace;
        font-size: 0.85em;
      }
      .qr {
        display: block;
        width: 100%;
        max-width: 300px;
        aspect-ratio: 1;
        margin: var(--rt-space) auto;
        background: #fff;
        border-radius: 6px;
      }
      @media print {
        :host {
          background: none;
        }
        header,
        .form,
        .result > section:not([aria-labelledby='handout-heading']),
        #handout-heading {
          display: none;
        }
        main {
          display: block;
          padding: 0;
        }
        section {
          border: 0;
          padding: 0;
          background: none;
        }
        .result {
          position: static;
          max-height: none;
          overflow: visible;
        }
      }
      @media (max-width: 900px) {
        main {
          grid-template-columns: 1fr;
        }
        .result {
          position: static;
        }
      }
    `,
];
