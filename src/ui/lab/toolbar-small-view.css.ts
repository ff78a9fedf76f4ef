import { css } from 'lit';
import { visuallyHidden } from '../controls/visually-hidden.css.ts';

/**
 * rt-view-toolbar in a small view (a phone, a laptop at 200 % zoom, a tablet's middle
 * column), where its buttons would lie over the camera's image, the ray legend and the ray
 * debugger's button: the camera and help buttons show only their icons (their names kept for
 * screen readers and in their tooltips), at the right of the top row, and the gizmo's groups
 * wrap at its left; the orbit, pan and zoom pads fold behind one small button (a four-way
 * arrow), and the view still turns by dragging, pinching, the wheel and the keys. The
 * 3D view (rt-scene-view) is the size container asked; on a wider view it is laid out as before.
 */
export const smallViewToolbarStyles = css`
  /* The gizmo's groups (left) wrap among themselves; the camera and help buttons keep to the right. */
  .top .start {
    display: contents;
  }
  .pads {
    display: contents;
  }
  .pads-toggle {
    display: none;
  }
  @container (max-width: 540px) {
    /* The top bar: the camera and help buttons (their names kept for screen readers and in
       their tooltips) stay at the right of its first row; the gizmo's groups wrap at the left. */
    .top {
      flex-wrap: nowrap;
    }
    .top .start {
      display: flex;
      flex-wrap: wrap;
      gap: 8px;
      min-width: 0;
    }
    .top .end {
      flex: none;
    }
    /* Narrower buttons, so that the gizmo's modes and the camera and help icons share a row in Dutch too. */
    .top button {
      padding: 0 6px;
    }
    .top .end .label {
      ${visuallyHidden}
    }
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
