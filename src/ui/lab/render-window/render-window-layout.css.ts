import { css } from 'lit';

/** The render window's frame: header, actions, the image stage, the footer and the stale-scene note. */
export const renderWindowLayout = css`
      :host {
        display: none;
        flex-direction: column;
        gap: 10px;
        box-sizing: border-box;
        min-height: 0;
        padding: 12px 16px;
        background: var(--rt-surface);
        color: var(--rt-text);
        font-family: var(--rt-font);
        border: 1px solid var(--rt-border);
        border-radius: var(--rt-radius);
        box-shadow: 0 12px 40px rgb(0 0 0 / 0.28);
      }
      :host([open]) {
        display: flex;
      }
      :host(:focus) {
        outline: none;
      }
      header,
      .actions,
      footer {
        display: flex;
        flex-wrap: wrap;
        align-items: center;
        gap: 8px 12px;
      }
      h2 {
        margin: 0;
        font-size: 1.15rem;
      }
      .size {
        flex: 1;
        color: var(--rt-muted);
        font-variant-numeric: tabular-nums;
      }
      .progress {
        flex: 1 1 240px;
        display: flex;
        align-items: center;
        gap: 8px;
      }
      progress {
        flex: 1;
        min-width: 80px;
        height: 10px;
        accent-color: var(--rt-accent);
      }
      .phase {
        min-width: 8.5em;
        font-variant-numeric: tabular-nums;
      }
      .left {
        color: var(--rt-muted);
        white-space: nowrap;
        font-variant-numeric: tabular-nums;
      }
      rt-image-compare,
      .placeholder {
        flex: 1;
        min-height: 0;
      }
      .placeholder {
        display: grid;
        place-items: center;
        padding: 16px;
        border-radius: 8px;
        background: color-mix(in srgb, var(--rt-text) 8%, var(--rt-bg));
        color: var(--rt-muted);
        text-align: center;
      }
      footer {
        min-height: var(--rt-target);
      }
      footer p {
        margin: 0;
      }
      .error {
        color: var(--rt-danger);
      }
      .stale {
        display: inline-flex;
        align-items: center;
        gap: 8px;
        padding: 2px 4px 2px 10px;
        border-radius: 8px;
        border: 1px solid color-mix(in srgb, #e8a317 60%, var(--rt-border));
        background: color-mix(in srgb, #e8a317 16%, var(--rt-surface));
      }
      .heavy {
    padding: 8px 12px;
    border-radius: 8px;
    border: 1px solid color-mix(in srgb, #e8a317 60%, var(--rt-border));
    background: color-mix(in srgb, #e8a317 16%, var(--rt-surface));
  }
  .heavy p {
    margin: 0 0 8px;
  }
  .heavy .choices {
    display: flex;
    flex-wrap: wrap;
    gap: 8px;
    margin-bottom: 8px;
  }
`;
