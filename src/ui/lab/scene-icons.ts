import { html, svg, type SVGTemplateResult, type TemplateResult } from 'lit';
import type { Color, LightType, ShapeKind } from '../../scene/scene.ts';
import { colorToHex } from '../controls/color-hex.ts';

/**
 * Small 20×20 pictures of the scene list's items: the shape filled with the object's colour
 * (or a light drawn in its colour), outlined in the text colour so they read on both themes.
 * The list also names each kind in words; a picture is never the only sign.
 */

export function shapeIcon(shape: ShapeKind, color: Color): TemplateResult {
  const fill = colorToHex(color);
  const body = {
    sphere: svg`<circle cx="10" cy="10" r="7" fill=${fill} />`,
    box: svg`<path d="M4 7 10 4 16 7 16 14 10 17 4 14Z" fill=${fill} /><path d="M4 7 10 10 16 7M10 10V17" fill="none" />`,
    cylinder: svg`<path d="M4 5v10c0 1.7 2.7 3 6 3s6-1.3 6-3V5" fill=${fill} /><ellipse cx="10" cy="5" rx="6" ry="2.5" fill=${fill} />`,
    plane: svg`<path d="M2 14 7 7H18L13 14Z" fill=${fill} />`,
    mesh: svg`<path d="M10 3 17 16H3Z" fill=${fill} /><path d="M10 3 9 16" fill="none" />`,
  }[shape];
  return icon(body);
}

export function lightIcon(type: LightType, color: Color): TemplateResult {
  const fill = colorToHex(color);
  const body = {
    point: svg`<circle cx="10" cy="8" r="5" fill=${fill} /><path d="M8 14h4M8 17h4" fill="none" />`,
    spot: svg`<path d="M8 3h4l5 14H3Z" fill=${fill} />`,
    area: svg`<rect x="3" y="4" width="14" height="6" fill=${fill} /><path d="M6 13v4M10 13v4M14 13v4" fill="none" />`,
  }[type];
  return icon(body);
}

export function cameraIcon(): TemplateResult {
  return icon(svg`<rect x="2" y="6" width="11" height="9" rx="1" fill="none" /><path d="M13 9l5-3v9l-5-3" fill="none" />`);
}

/** A padlock: an item the level keeps where it is (ui.movable). */
export function lockIcon(): TemplateResult {
  return icon(svg`<rect x="4.5" y="9" width="11" height="8" rx="1.5" fill="none" /><path d="M7 9V6.5a3 3 0 0 1 6 0V9" fill="none" />`);
}

function icon(body: SVGTemplateResult): TemplateResult {
  return html`<svg class="icon" viewBox="0 0 20 20" width="20" height="20" aria-hidden="true" stroke="currentColor" stroke-width="1.3" stroke-linejoin="round">${body}</svg>`;
}
