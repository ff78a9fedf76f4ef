import { css } from 'lit';

/**
 * The orbit, pan and zoom pads of rt-view-toolbar in a small view (a phone, a laptop at
 * 200 % zoom, a tablet's middle column): there is no room for them beside the camera's image
 * in the view's lower left, so they fold behind one button. The view still turns by
 * dragging, pinching, the wheel and the keys. The toolbar is a size container as big as the
 * view; on a wider view the button is hidden and the pads are laid out as before.
 */
export const foldedPadsStyles = css`
  .pads {
    display: contents;
  }
  .pads-toggle {
    display: none;
  }
  @container (max-width: 540px) {
    .bottom-right {
      left: auto;
      flex-direction: column;
      flex-wrap: nowrap;
    }
    .pads {
      display: flex;
      flex-wrap: wrap;
      justify-content: flex-end;
      gap: 8px;
    }
    .bottom-right:not([data-open]) .pads {
      display: none;
    }
    .pads-toggle {
      display: inline-flex;
      gap: 2px;
      padding: 0 6px;
      pointer-events: auto;
      border: 1px solid var(--rt-border);
      background: color-mix(in srgb, var(--rt-surface) 94%, transparent);
      box-shadow: 0 2px 8px rgb(0 0 0 / 0.12);
    }
    .pads-toggle::after {
      content: ' ▴' / '';
    }
    .bottom-right[data-open] .pads-toggle::after {
      content: ' ▾' / '';
    }
  }
`;
