import { msg } from '@lit/localize';
import { html, nothing, type TemplateResult } from 'lit';
import { CASE_MARK_COLORS, CELL_FILL_COLORS, SHADING_VECTOR_COLORS } from '../../../quest/code-labs/case-drawing.ts';
import type { CaseFailure, LabAnswer, Rgb } from '../../../quest/code-labs/code-lab-grading.ts';
import type { CodeLab } from '../../../quest/code-labs/code-goal.ts';
import { linearToSrgb } from '../../../tracer/srgb.ts';
import { labValue } from './lab-numbers.ts';

/** A mark as the view draws it, in its colour; hidden from screen readers, as the words beside it say what it is. */
const mark = (color: string, shape: string) => html`<span aria-hidden="true" style="color: ${color}">${shape}</span>`;

/** A shading vector's letter, after a square of its colour in the view (the letter itself in the text's colour, to read on any theme). */
const letter = (color: string, name: string) => html`${mark(color, '■')} <strong>${name}</strong>`;

const isColour = (answer: LabAnswer): answer is Rgb => answer !== null && typeof answer === 'object' && 'r' in answer;

/** A colour as a screen shows it: each channel clamped to 0…1 and sRGB-encoded (a negative channel shows as black). */
function screenColour({ r, g, b }: Rgb): string {
  const byte = (light: number) => Math.round(255 * linearToSrgb(Math.min(1, Math.max(0, light))));
  return `rgb(${byte(r)}, ${byte(g)}, ${byte(b)})`;
}

/** A square of the answer's colour with its value (`text`); an answer that is not a colour is only spelled out. */
function swatch(answer: LabAnswer, text: string): TemplateResult {
  const square = isColour(answer) ? html`<span aria-hidden="true" class="swatch" style="background: ${screenColour(answer)}"></span>` : nothing;
  return html`${square}<code>${text}</code>`;
}

/**
 * What the 3D view shows of a failing case, with the marks' colours and shapes: the ray labs'
 * ray and answers (● expected, ◆ got), or the Phong lab's point with its vectors and the two
 * colours, shown as squares with their values (the answers are colours, not places).
 */
export function caseLegend(lab: CodeLab, failure: CaseFailure): TemplateResult {
  if (lab === 'phong') {
    return html`<p class="legend">
      ${msg('Drawn in the 3D view: the point on a piece of its surface, with')} <strong>N</strong>: ${msg('the normal;')}
      ${letter(SHADING_VECTOR_COLORS.light, 'L')}: ${msg('toward the light (the orange ball);')} ${letter(SHADING_VECTOR_COLORS.eye, 'V')}: ${msg('toward the eye;')}
      ${letter(SHADING_VECTOR_COLORS.mirror, 'R')}: ${msg('L mirrored about the normal.')}<br />
      ${msg('Expected:')} ${swatch(failure.labCase.expected, labValue(failure.labCase.expected))}; ${msg('got:')} ${swatch(failure.gotValue, labValue(failure.got))}.
    </p>`;
  }
  return html`<p class="legend">
    ${msg('Drawn in the 3D view: the case’s ray and object;')} ${mark(CASE_MARK_COLORS.expected, '●')} ${msg('expected: the tracer’s answer;')}
    ${mark(CASE_MARK_COLORS.got, '◆')} ${msg('got: your function’s answer.')}
  </p>`;
}

/** What the 3D view shows of a failing run of the samples lab: the pixel, its cells, the run's points and what is wrong with them. */
export function runLegend(): TemplateResult {
  return html`<p class="legend">
    ${msg('Drawn in the 3D view: the pixel with its grid of cells and this run’s points;')} ${mark(CASE_MARK_COLORS.got, '◆')} ${msg('a point outside the pixel;')}
    ${mark(CELL_FILL_COLORS.empty, '■')} ${msg('a cell with no point;')} ${mark(CELL_FILL_COLORS.crowded, '■')} ${msg('a cell with two points or more.')}
  </p>`;
}

/** What the 3D view shows of a failing run of directions (cosine-bounce-lab.ts). */
export function directionLegend(): TemplateResult {
  return html`<p class="legend">
    ${msg('Drawn in the 3D view, turned so that the normal points up: the normal and the cosine lobe, the sphere of diameter 1 on the surface;')}
    ${mark(CASE_MARK_COLORS.expected, '●')} ${msg('expected: the tips of the tracer’s directions;')} ${mark(CASE_MARK_COLORS.got, '◆')}
    ${msg('got: the tips of yours.')}
  </p>`;
}
