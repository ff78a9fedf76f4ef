import { msg } from '@lit/localize';
import { html, type TemplateResult } from 'lit';

/**
 * The ray colours' legend over the 3D view, with the button that opens and closes it. On a
 * wide screen the legend is always shown and the button hidden (lab-layout.css.ts); on a
 * phone the small view has no room for it, so it starts closed behind the button, which a tap
 * or Enter opens.
 */
export function viewLegendBox(open: boolean, toggle: () => void): TemplateResult {
  return html`<div class="view-legend" ?data-open=${open}>
    <button class="legend-toggle" aria-expanded=${open ? 'true' : 'false'} aria-controls="view-legend" @click=${toggle}>${msg('Ray colours')}</button>
    <rt-ray-legend id="view-legend"></rt-ray-legend>
  </div>`;
}
