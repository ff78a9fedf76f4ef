import { html, svg } from 'lit';

/**
 * Fill patterns for the dashboard's bars, so that segments differ by texture as well as by
 * colour (colour is never the only signal). Each element puts PATTERN_DEFS in its own
 * shadow root once; a fill then refers to `url(#pattern-<name>)` over its base colour.
 */
export const PATTERN_DEFS = html`<svg width="0" height="0" style="position:absolute" aria-hidden="true">
  <defs>
    <pattern id="pattern-hatch" width="6" height="6" patternUnits="userSpaceOnUse" patternTransform="rotate(45)">
      <line x1="0" y1="0" x2="0" y2="6" stroke="rgb(0 0 0 / 45%)" stroke-width="2.5"></line>
    </pattern>
    <pattern id="pattern-hatch-sparse" width="10" height="10" patternUnits="userSpaceOnUse" patternTransform="rotate(45)">
      <line x1="0" y1="0" x2="0" y2="10" stroke="rgb(0 0 0 / 35%)" stroke-width="1.5"></line>
    </pattern>
    <pattern id="pattern-dots" width="6" height="6" patternUnits="userSpaceOnUse">
      <circle cx="3" cy="3" r="1.6" fill="rgb(255 255 255 / 70%)"></circle>
    </pattern>
    <pattern id="pattern-dots-sparse" width="10" height="10" patternUnits="userSpaceOnUse">
      <circle cx="5" cy="5" r="1.4" fill="rgb(0 0 0 / 40%)"></circle>
    </pattern>
  </defs>
</svg>`;

export type PatternName = 'hatch' | 'hatch-sparse' | 'dots' | 'dots-sparse' | null;

/**
 * A filled rectangle: the base colour, then the pattern over it. Coordinates may be
 * percentages ("25%"): bars drawn that way stretch with the page without stretching text.
 */
export function patternedRect(
  x: number | string,
  y: number,
  width: number | string,
  height: number,
  fill: string,
  pattern: PatternName,
  className = 'segment',
) {
  return svg`<rect class=${className} x=${x} y=${y} width=${width} height=${height} fill=${fill}></rect>
    ${pattern ? svg`<rect x=${x} y=${y} width=${width} height=${height} fill="url(#pattern-${pattern})" pointer-events="none"></rect>` : null}`;
}
