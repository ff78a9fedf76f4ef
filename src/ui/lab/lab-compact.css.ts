import { css } from 'lit';
import { visuallyHidden } from '../controls/visually-hidden.css.ts';

/**
 * Small screens: a phone, or a laptop at 200 % zoom (1366×768 lays out 683×384 CSS px). The
 * 3D view and the level's tasks must be on screen together, so the page does not scroll:
 * the view keeps its place and the column beside it (below it on a phone held upright)
 * shows either the tasks or the panels, chosen with the two buttons over that column
 * (side-switch.ts); each scrolls in its own box, so a new current task scrolls into view
 * without moving the view. The header is one slim row (the title is read out, not shown).
 * The render window takes the whole screen; the ray legend folds away behind a button.
 *
 * Which layout: short screens up to 900 px wide (a landscape phone, 200 % zoom) put the
 * column beside the view; narrow ones (an upright phone) put it below. Wider or taller
 * screens keep the three columns of lab-layout.css.ts, each scrolling on its own.
 */
const compact = css`
  @media (max-width: 559px), (max-width: 760px) and (min-height: 541px), (max-width: 900px) and (max-height: 540px) {
    :host,
    :host([free-lab]) {
      grid-template-columns: minmax(0, 1fr);
    }
    /* One row at 683 px (the buttons a little smaller), two on an upright phone. */
    header {
      flex-wrap: wrap;
      row-gap: 4px;
      padding: 4px var(--rt-space);
      font-size: 0.875rem;
    }
    .header-actions {
      gap: 4px;
    }
    .header-actions button {
      padding: 0 8px;
    }
    header h1 {
      ${visuallyHidden}
    }
    .side-switch {
      display: flex;
    }
    :host(:not([panels-shown])) .sidebar,
    :host([panels-shown]) .tasks {
      display: none;
    }
    /* The free lab has no tasks: its column is the panels, without the switch. */
    :host([free-lab]) .side-switch,
    :host([free-lab]) .tasks {
      display: none;
    }
    :host([free-lab]) .sidebar {
      display: flex;
    }
    .sidebar,
    .tasks {
      border: 0;
      min-height: 0;
    }
    /* The map spans the rows below the header; sized by them, not by its content, so that it
       does not stretch the switch's row (and the view with it) while it is open. */
    rt-level-map,
    rt-survey-page {
      contain: size;
    }
    /* The camera's image in the view's lower left at its smallest (26 px cells, the caption
       wrapped to the grid's width), beside the pads' small button on the right; a large
       screen (12 × 9) scrolls in it rather than cover the whole view. */
    rt-screen-preview {
      width: min-content;
      min-width: 0;
      max-width: calc(100% - 90px);
      max-height: 55%;
    }
    /* Below the view's top bar, which the gizmo's option buttons make two rows high. */
    :host([gizmo-options]) .view-legend,
    :host([gizmo-options]) rt-ray-debugger:not([open]) {
      top: 100px;
    }
    /* Unfolded, the pads need the view's lower part: the image steps aside (its place kept, so the view's framing stays). */
    :host([pads-open]) rt-screen-preview {
      visibility: hidden;
    }
    rt-render-window {
      position: fixed;
      inset: 0;
      z-index: 40;
    }
    /* Over the small view the legend folds away behind a small button; open, it is smaller,
       and taps go through it to the scene. */
    .view-legend {
      top: 52px;
      width: auto;
      max-width: 45%;
      padding: 0;
      background: none;
      box-shadow: none;
      font-size: 0.75rem;
    }
    .legend-toggle {
      display: block;
      box-shadow: var(--rt-shadow);
    }
    .legend-toggle::after {
      content: ' ▾' / '';
    }
    .view-legend[data-open] .legend-toggle::after {
      content: ' ▴' / '';
    }
    .view-legend:not([data-open]) rt-ray-legend {
      display: none;
    }
    .view-legend rt-ray-legend {
      margin-top: 4px;
      padding: 2px 6px;
      border-radius: var(--rt-radius);
      background: var(--rt-surface);
      box-shadow: var(--rt-shadow);
      opacity: 0.92;
      pointer-events: none;
    }
  }

  /* Beside the view: a landscape phone, a laptop at 200 % zoom. The view keeps at least 320 px. */
  @media (min-width: 560px) and (max-width: 900px) and (max-height: 540px) {
    :host,
    :host([free-lab]) {
      grid-template-columns: minmax(320px, 1fr) minmax(240px, 360px);
      grid-template-rows: auto auto minmax(0, 1fr);
    }
    main {
      grid-area: 2 / 1 / 4 / 2;
    }
    .side-switch {
      grid-area: 2 / 2;
      border-left: 1px solid var(--rt-border);
    }
    .sidebar,
    .tasks {
      grid-area: 3 / 2;
      border-left: 1px solid var(--rt-border);
    }
    :host([free-lab]) .sidebar {
      grid-area: 2 / 2 / 4 / 3;
    }
    rt-level-map,
    rt-survey-page {
      grid-column: 1 / -1;
      grid-row: 2 / -1;
    }
    /* Open, the ray debugger takes the column beside the view (as wide as the grid makes it),
       not the view's lower half: the view keeps its 320 px and shows the rays being stepped. */
    rt-ray-debugger[open] {
      top: 0;
      bottom: 0;
      left: 100%;
      right: auto;
      width: clamp(240px, calc(100vw - 320px), 360px);
      height: auto;
    }
    /* A message at the top of the task column (toast-place.ts) goes under its switch: the
       slim header and the switch end at about 82 px. */
    :host(:not([free-lab])) rt-toast[data-place='top'] {
      inset: 88px var(--rt-space) auto auto;
    }
  }

  /* Below the view: a phone held upright. */
  @media (max-width: 559px), (max-width: 760px) and (min-height: 541px) {
    :host {
      grid-template-rows: auto minmax(200px, 45%) auto minmax(0, 1fr);
    }
    main {
      grid-area: 2 / 1;
    }
    .side-switch {
      grid-area: 3 / 1;
      border-top: 1px solid var(--rt-border);
    }
    .sidebar,
    .tasks {
      grid-area: 4 / 1;
    }
    :host([free-lab]) .sidebar {
      grid-area: 3 / 1 / 5 / 2;
      border-top: 1px solid var(--rt-border);
    }
    rt-level-map,
    rt-survey-page {
      grid-column: 1;
      grid-row: 2 / -1;
    }
    /* Open, the ray debugger covers the view: half of a view 200 px high would show no part of it. */
    rt-ray-debugger[open] {
      top: 0;
      height: auto;
    }
    /* The column's top is below the view here: messages keep the bottom corner, not the view. */
    :host(:not([free-lab])) rt-toast[data-place='top'] {
      inset: auto var(--rt-space) calc(var(--rt-space) * 2) auto;
    }
  }
`;

/** The buttons over the column of a small screen that choose between the tasks and the panels (hidden on wide screens). */
const sideSwitch = css`
  .side-switch {
    display: none;
    gap: 4px;
    padding: 4px var(--rt-space);
    background: var(--rt-surface);
  }
  /* Each button as wide as its name, the rest shared: a long name ("Scène en instellingen") keeps to one line. */
  .side-switch button {
    flex: 1 1 auto;
    font: inherit;
    font-size: 0.875rem;
    min-height: var(--rt-target);
    padding: 0 8px;
    border-radius: 8px;
    border: 1px solid var(--rt-control-border);
    background: var(--rt-surface);
    color: var(--rt-text);
    cursor: pointer;
  }
  .side-switch button[aria-pressed='true'] {
    background: var(--rt-accent-soft);
    border-color: var(--rt-accent);
    font-weight: 600;
  }
  .side-switch button:focus-visible {
    outline: 3px solid var(--rt-focus);
    outline-offset: 2px;
  }
`;

/** The lab's layout on small screens, after the wide grid. */
export const labCompact = [sideSwitch, compact];
