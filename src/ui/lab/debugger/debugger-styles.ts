import { css } from 'lit';

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
    font-size: 0.75rem;
    margin-left: auto;
    white-space: nowrap;
  }
  .now-line {
    display: flex;
    align-items: baseline;
    gap: 10px;
  }
  .now {
    margin: 0;
    font-size: 0.85rem;
    min-height: 1.3em;
  }
  .columns {
    display: grid;
    grid-template-columns: minmax(0, 1.1fr) minmax(0, 1fr);
    gap: 10px;
    min-height: 0;
    flex: 1;
  }
  .columns > * {
    min-height: 0;
    overflow-y: auto;
  }
  .columns > :focus-visible {
    outline: 3px solid var(--rt-focus);
    outline-offset: -3px;
  }
  .why {
    font-size: 0.8rem;
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
  @media (max-width: 1100px) {
    .columns {
      grid-template-columns: minmax(0, 1fr);
    }
  }
`;
