import { msg } from '@lit/localize';
import { css, html, nothing, type TemplateResult } from 'lit';
import { styleMap } from 'lit/directives/style-map.js';
import { timeGradient } from '../../../view/time-colors.ts';

/**
 * The ray legend's key for "Colour by time" (issue 37: it had none): the ramp rays are drawn
 * in by their moment, from "shutter opens" to "shutter closes". Shown only while the option
 * is on; the rays without a time keep their type's colour, so the legend's entries stay.
 */
export function timeKey(colorByTime: boolean): TemplateResult | typeof nothing {
  if (!colorByTime) return nothing;
  return html`<div class="time-key" data-key="time" role="group" aria-label=${msg('Colour by time: dark violet when the shutter opens, through teal and green, to yellow when it closes')}>
    <span class="time-ramp" style=${styleMap({ background: timeGradient() })} aria-hidden="true"></span>
    <span class="time-ends" aria-hidden="true"><span>${msg('shutter opens')}</span><span>${msg('shutter closes')}</span></span>
  </div>`;
}

export const timeKeyStyles = css`
  .time-key {
    display: grid;
    gap: 2px;
    margin-top: 6px;
    font-size: 0.85em;
    color: var(--rt-muted);
  }
  .time-ramp {
    height: 8px;
    border-radius: 4px;
    box-shadow: 0 0 0 1px color-mix(in srgb, var(--rt-text) 35%, transparent);
  }
  .time-ends {
    display: flex;
    justify-content: space-between;
    gap: 8px;
  }
`;
