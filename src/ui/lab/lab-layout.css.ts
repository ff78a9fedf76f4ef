import { css } from 'lit';
import { labCompact } from './lab-compact.css.ts';

/**
 * The lab's grid: the header over three columns (panels, the 3D view, the tasks), the level
 * map over all of them below the header, the render window over the view, the toast over the
 * task column (rt-toast.ts).
 */
const labGrid = css`
    :host {
      display: grid;
      grid-template-columns: minmax(260px, 300px) 1fr minmax(220px, 280px);
      grid-template-rows: auto 1fr;
      height: 100vh;
      overflow: hidden;
    }
    header {
      grid-column: 1 / -1;
      display: flex;
      align-items: center;
      gap: var(--rt-space);
      padding: 6px calc(var(--rt-space) * 2);
      background: var(--rt-surface);
      border-bottom: 1px solid var(--rt-border);
    }
    h1 {
      font-size: 1.15rem;
      margin: 0 auto 0 0;
    }
    /* Positioned, so that what sits absolutely in them (visually hidden text) scrolls with them instead of stretching the page. */
    .sidebar,
    .tasks {
      position: relative;
      overflow-y: auto;
      background: var(--rt-surface);
      padding: var(--rt-space);
      display: flex;
      flex-direction: column;
      gap: var(--rt-space);
    }
    /* Every area has its cell: the level map, placed over row 2, must not push them into a row of their own. */
    .sidebar {
      grid-area: 2 / 1;
      border-right: 1px solid var(--rt-border);
    }
    main {
      grid-area: 2 / 2;
    }
    .tasks {
      grid-area: 2 / 3;
      border-left: 1px solid var(--rt-border);
      color: var(--rt-muted);
    }
    .your-data {
      margin-top: auto;
      padding-top: var(--rt-space);
      border-top: 1px solid var(--rt-border);
    }
    .your-data h2 {
      font-size: 0.875rem;
      margin: 0 0 var(--rt-space);
      color: var(--rt-muted);
    }
    .header-actions {
      display: flex;
      align-items: center;
      gap: var(--rt-space);
      flex-wrap: wrap;
    }
    .header-actions button:not(.primary),
    .welcome button,
    .legend-toggle {
      font: inherit;
      min-height: var(--rt-target);
      padding: 0 12px;
      border-radius: 8px;
      border: 1px solid var(--rt-control-border);
      background: var(--rt-surface);
      color: var(--rt-text);
      cursor: pointer;
    }
    .header-actions button:focus-visible,
    .welcome button:focus-visible,
    .legend-toggle:focus-visible {
      outline: 3px solid var(--rt-focus);
      outline-offset: 2px;
    }
    /* The map (and the closing survey's page) covers the whole lab below the header: the level behind it waits. */
    rt-level-map,
    rt-survey-page {
      grid-column: 1 / -1;
      grid-row: 2;
      z-index: 30;
      min-height: 0;
    }
    /* The size of the task panel's text below it, so the two read as one column. */
    .welcome {
      padding: 10px;
      border-radius: var(--rt-radius);
      background: var(--rt-accent-soft);
      color: var(--rt-text);
      font-size: 0.875rem;
      line-height: 1.3;
    }
    .welcome p {
      margin: 0 0 8px;
    }
    .empty-sidebar {
      color: var(--rt-muted);
      font-size: 0.875rem;
    }
    main {
      position: relative;
      min-width: 0;
      min-height: 0;
    }
    rt-scene-view {
      position: absolute;
      inset: 0;
    }
    .lab-load-problems {
      position: absolute;
      top: 64px;
      left: 50%;
      z-index: 5;
      display: grid;
      gap: 8px;
      width: min(60ch, calc(100% - 24px));
      transform: translateX(-50%);
    }
    rt-screen-preview {
      position: absolute;
      left: var(--rt-space);
      bottom: var(--rt-space);
      z-index: 5;
      /* A thumbnail of the camera's image: big enough to click a pixel (its cells are at least
         26 px, so a wide screen widens it), small enough to leave the scene in view. */
      width: max-content;
      min-width: min(240px, 30%);
      max-width: 60%;
      overflow: auto;
      /* On a card like the view's buttons: its caption must stay readable over a light floor in the dark theme. */
      box-sizing: border-box;
      padding: 4px;
      border-radius: var(--rt-radius);
      background: var(--rt-surface);
      box-shadow: var(--rt-shadow);
    }
    /* Out of the way of the chosen pixel's rays: below the view's top right buttons (preview-place.ts, TOP_RIGHT_TOP). */
    rt-screen-preview[data-place='top-right'] {
      left: auto;
      bottom: auto;
      right: var(--rt-space);
      top: 148px;
    }
    /* The ray colours over the view, below its top toolbar, in levels whose ray panel does not show them. */
    .view-legend {
      position: absolute;
      top: 60px;
      left: var(--rt-space);
      z-index: 5;
      width: 10.5em;
      box-sizing: border-box;
      padding: 6px 8px;
      border-radius: var(--rt-radius);
      background: var(--rt-surface);
      box-shadow: var(--rt-shadow);
    }
    /* Its button only folds it away on a phone (below); it looks like the header's buttons. */
    .legend-toggle {
      display: none;
    }
    /* The ray debugger: its button under the view's top-right buttons; open, a dock over the view's lower half. */
    rt-ray-debugger {
      position: absolute;
      z-index: 6;
      top: 60px;
      right: var(--rt-space);
    }
    /* With the gizmo's options the view's top bar can wrap to two rows (Dutch labels at
       1366×768: "Toon zijn stralen", "Camerabeeld" and "Hulp" go to the second row): the
       button goes under both, not over them. */
    :host([gizmo-options]) rt-ray-debugger:not([open]) {
      top: 100px;
    }
    rt-ray-debugger[open] {
      top: auto;
      bottom: var(--rt-space);
      left: var(--rt-space);
      right: var(--rt-space);
      height: 46%;
    }
    /* The open debugger's dock starts at 54 % of the view, less the gap: the legend keeps above it,
       in two columns (rt-ray-legend's grid fills the width), and scrolls if it is still too long
       (a time or path key under the rays: a path's width and lobe stay in reach). :where keeps small screens' folding legend (lab-compact.css.ts) in charge. */
    :where(main:has(rt-ray-debugger[open])) .view-legend {
      width: 21em;
      max-height: calc(54% - 60px - 2 * var(--rt-space));
      overflow-y: auto;
    }
    /* The debugger shows its pixel; another is chosen on the camera's screen in 3D (or after closing it). */
    main:has(rt-ray-debugger[open]) rt-screen-preview {
      display: none;
    }
    rt-render-window {
      position: absolute;
      inset: var(--rt-space);
      z-index: 10;
    }
    .primary {
      font: inherit;
      min-height: var(--rt-target);
      padding: 0 14px;
      border-radius: 8px;
      border: 0;
      background: var(--rt-accent);
      color: var(--rt-accent-text);
      cursor: pointer;
      font-weight: 600;
    }
    .primary:focus-visible {
      outline: 3px solid var(--rt-focus);
      outline-offset: 2px;
    }
    /* Messages go to an end of the task column that covers neither the level's intro nor the
       current task (toast-place.ts): its foot (rt-toast.ts) or, here, its top under the header… */
    :host(:not([free-lab])) rt-toast[data-place='top'] {
      inset: 52px var(--rt-space) auto auto;
    }
    /* …or, when either end would cover the level's intro or the current task, over the foot of the panels column. */
    :host(:not([free-lab])) rt-toast[data-place='panels'] {
      inset: auto auto calc(var(--rt-space) * 2) var(--rt-space);
    }
    /* Narrow screens (1024 px tablets) keep the tasks and narrow both sides; the free lab gives the tasks' room to the view. */
    @media (max-width: 1180px) {
      :host {
        grid-template-columns: minmax(220px, 240px) 1fr minmax(240px, 260px);
      }
      :host([free-lab]) {
        grid-template-columns: minmax(240px, 280px) 1fr;
      }
      :host([free-lab]) .tasks {
        display: none;
      }
      /* Without the task column, messages go over the panels (rt-toast.ts: never over the view). */
      :host([free-lab]) rt-toast {
        inset: auto auto calc(var(--rt-space) * 2) var(--rt-space);
      }
    }
`;

/** The lab's styles: the wide grid, then the small screens' layout (lab-compact.css.ts). */
export const labLayout = [labGrid, ...labCompact];
