import { css } from 'lit';

/**
 * What the dashboard's charts share: a grid of label | chart (| count) rows, bars drawn
 * across the whole cell, and a legend of small swatches under the chart.
 */
export const chartStyles = css`
  :host {
    display: block;
  }
  .label {
    text-align: right;
    overflow-wrap: anywhere;
    font-size: 0.9rem;
  }
  svg.bar {
    width: 100%;
    display: block;
  }
  .outline {
    fill: none;
    stroke: var(--rt-border);
  }
  .legend {
    display: flex;
    flex-wrap: wrap;
    gap: 4px 16px;
    margin: var(--rt-space) 0 0;
    padding: 0;
    list-style: none;
    font-size: 0.85rem;
  }
  .legend svg {
    width: 22px;
    height: 14px;
    vertical-align: -2px;
  }
`;

/** The dashboard's tables of numbers: scrolling sideways on a narrow screen, figures aligned. */
export const tableStyles = css`
  :host {
    display: block;
    overflow-x: auto;
  }
  table {
    border-collapse: collapse;
    font-size: 0.9rem;
    font-variant-numeric: tabular-nums;
  }
  caption {
    text-align: left;
    font-weight: 600;
    padding-bottom: 4px;
  }
  th,
  td {
    padding: 4px 8px;
    border-bottom: 1px solid var(--rt-border);
  }
  thead th {
    color: var(--rt-muted);
    font-weight: 600;
    vertical-align: bottom;
  }
`;

/** A table with a row per task or question across the page: its first column names the row, left and in plain weight. */
export const namedRowsTableStyles = css`
  table {
    width: 100%;
  }
  th:first-child {
    text-align: left;
    font-weight: normal;
  }
`;
