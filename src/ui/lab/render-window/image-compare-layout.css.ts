import { css } from 'lit';
import { SIDE_BY_SIDE_GAP } from './image-zoom.ts';

/** Space kept free around the image(s) inside the frame, in CSS pixels. */
export const FRAME_PADDING = 8;

/** The image viewer's layout: toolbar, scrolling frame, image boxes, the traced canvas's window, chips and the slider's divider. */
export const imageCompareLayout = css`
      :host {
        display: flex;
        flex-direction: column;
        min-height: 0;
        gap: 8px;
      }
      .toolbar {
        display: flex;
        flex-wrap: wrap;
        align-items: center;
        gap: 8px 20px;
      }
      .readout {
        min-width: 4.5em;
        font-variant-numeric: tabular-nums;
        color: var(--rt-muted);
      }
      .note {
        margin: 0;
        color: var(--rt-muted);
        font-size: 0.9rem;
      }
      input[type='range'] {
        width: 140px;
        min-height: var(--rt-target);
        accent-color: var(--rt-accent);
      }
      .frame {
        flex: 1;
        min-height: 0;
        display: flex;
        overflow: auto;
        border-radius: 8px;
        background: color-mix(in srgb, var(--rt-text) 8%, var(--rt-bg));
      }
      .frame.fit {
        overflow: hidden;
      }
      /* Auto margins centre the content while it is smaller than the frame and fall to 0 when
         it is larger, so that it scrolls to every edge (centring with place-items would cut
         off its left and top). */
      .content {
        margin: auto;
        padding: ${FRAME_PADDING}px;
        display: flex;
        gap: ${SIDE_BY_SIDE_GAP}px;
      }
      .pixelated {
        image-rendering: pixelated;
      }
      .image {
        position: relative;
        flex: none;
        background: #000;
      }
      ::slotted(canvas) {
        display: block;
        width: 100%;
        height: 100%;
      }
      .window {
        position: absolute;
      }
      .layer {
        position: absolute;
        inset: 0;
      }
      .chip {
        position: absolute;
        top: 6px;
        left: 6px;
        max-width: calc(50% - 12px);
        padding: 2px 8px;
        border-radius: 6px;
        background: rgb(0 0 0 / 0.7);
        color: #fff;
        font-size: 0.8rem;
        pointer-events: none;
        z-index: 1; /* above the divider's line */
      }
      .chip.right {
        left: auto;
        right: 6px;
        text-align: right;
      }
      /* The divider: a thin line, with a 32 px wide strip around it to grab (touch). */
      .divider {
        position: absolute;
        top: 0;
        bottom: 0;
        width: var(--rt-target);
        transform: translateX(-50%);
        cursor: ew-resize;
        touch-action: none;
      }
      .divider::before {
        content: '';
        position: absolute;
        top: 0;
        bottom: 0;
        left: 15px;
        width: 2px;
        background: #fff;
        box-shadow: 0 0 0 1px rgb(0 0 0 / 0.5);
      }
      .grip {
        position: absolute;
        top: 50%;
        left: 0;
        width: var(--rt-target);
        height: var(--rt-target);
        transform: translateY(-50%);
        border-radius: 50%;
        background: #fff;
        color: #000;
        box-shadow: 0 1px 4px rgb(0 0 0 / 0.5);
        display: grid;
        place-items: center;
        font-size: 1rem;
      }
    `;
