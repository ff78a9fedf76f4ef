import { css } from 'lit';
import { visuallyHidden } from '../../controls/visually-hidden.css.ts';

/**
 * The ray debugger's card: a header, the step buttons, the sentence of the step, then the
 * pseudocode beside the equation (one column when narrow). The lab places the element.
 */
export const debuggerStyles = css`
  :host {
    display: block;
  }
  .opener {
    box-shadow: var(--rt-shadow);
    font-weight: 600;
  }
  .card {
    container-type: inline-size;
    display: flex;
    flex-direction: column;
    gap: 6px;
    box-sizing: border-box;
    height: 100%;
    padding: 8px 10px;
    border-radius: var(--rt-radius);
    background: var(--rt-surface);
    box-shadow: var(--rt-shadow);
    overflow: hidden;
  }
  .card:focus-visible {
    outline: 3px solid var(--rt-focus);
    outline-offset: 2px;
  }
  header {
    display: flex;
    flex-wrap: wrap;
    align-items: center;
    gap: 6px 10px;
  }
  h2 {
    margin: 0;
    font-size: 0.95rem;
  }
  h3 {
    margin: 6px 0 2px;
    font-size: 0.85rem;
  }
  .where {
    color: var(--rt-muted);
    font-size: 0.85rem;
  }
  .close {
    margin-left: auto;
  }
  .controls {
    display: flex;
    flex-wrap: wrap;
    align-items: center;
    gap: 6px;
  }
  .controls button {
    min-height: 30px;
    padding: 0 10px;
  }
  .keys {
    color: var(--rt-muted);
    font-size: 0.72rem;
    white-space: nowrap;
  }
  /* Too narrow for the hint beside the buttons: their titles and aria-keyshortcuts still name the keys. */
  @container (max-width: 880px) {
    .keys {
      display: none;
    }
  }
  .now {
    margin: 0;
    font-size: 0.85rem;
    min-height: 1.3em;
  }
  /* The pseudocode, the tree of rays with the running sum, the hit's equation: each scrolls on its own, its sum stays in view. */
  .columns {
    display: grid;
    grid-template-columns: minmax(0, 0.8fr) minmax(0, 1fr) minmax(0, 1.2fr);
    gap: 8px;
    min-height: 0;
    flex: 1;
  }
  .columns > * {
    min-height: 0;
  }
  .columns > rt-debug-code {
    overflow-y: auto;
  }
  .right {
    display: flex;
    flex-direction: column;
    gap: 4px;
  }
  .right > rt-debug-equation {
    flex: 1;
  }
  .columns > :focus-visible {
    outline: 3px solid var(--rt-focus);
    outline-offset: -3px;
  }
  .why {
    flex: none;
    max-height: 40%;
    overflow-y: auto;
    font-size: 0.76rem;
  }
  .why p,
  .why ul {
    margin: 0;
  }
  .why ul {
    padding-left: 1.2em;
  }
  .ask p,
  .problem {
    margin: 0 0 6px;
  }
  /* A small screen's dock (200 % zoom, a phone: about 360 px wide) has no room for columns:
     the three parts stand one under the other and scroll together under the pinned step
     buttons; the pseudocode and the tree keep a short box of their own (each keeps its
     current line in view), and the tree's running sum stays under its rows. */
  @container (max-width: 560px) {
    .columns {
      display: flex;
      flex-direction: column;
      overflow-y: auto;
    }
    .columns > rt-debug-code {
      flex: none;
      max-height: 6rem;
    }
    /* As high as the column's box: scrolled to, its rows and the sum under them fill it. */
    .columns > rt-debug-tree {
      flex: none;
      height: 100%;
      min-height: 9rem;
    }
    .right,
    .right > rt-debug-equation {
      flex: none;
    }
    .why {
      max-height: none;
    }
    /* The pixel, the step and Close on the first row, the step buttons under them. */
    .controls {
      order: 1;
    }
    /* The region is still named "Ray debugger"; the pixel and the step keep the first row. */
    h2 {
      ${visuallyHidden}
    }
  }
  /* Narrow: the pseudocode above the tree, the equation beside both. */
  @media (max-width: 1100px) {
    .columns {
      grid-template-columns: minmax(0, 1fr) minmax(0, 1fr);
      grid-template-rows: minmax(0, 1fr) minmax(0, 1fr);
    }
    .right {
      grid-column: 2;
      grid-row: 1 / span 2;
    }
  }
`;
