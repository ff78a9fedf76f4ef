import { msg } from '@lit/localize';
import { css, html, nothing, type TemplateResult } from 'lit';

/**
 * What the pupil's question pages share (the closing survey, the concept test): each question
 * a card (a fieldset, its legend the numbered question) that turns red and says what is
 * wrong under it, and a "Hand in" row with the count of what still needs an answer.
 */
export const questionFormStyles = css`
  fieldset {
    border: 1px solid var(--rt-border);
    border-radius: var(--rt-radius);
    background: var(--rt-surface);
    margin: 0 0 12px;
    padding: 12px 16px;
    /* A fieldset is as wide as its widest line by default: long options must wrap instead. */
    min-width: 0;
    overflow-wrap: anywhere;
  }
  fieldset[aria-invalid='true'] {
    border-color: var(--rt-danger);
    border-width: 2px;
  }
  legend {
    font-weight: 600;
    padding: 0 4px;
  }
  .actions {
    display: flex;
    flex-wrap: wrap;
    gap: 12px;
    align-items: center;
  }
`;

export interface QuestionCard {
  /** The question's id: the card's `data-question`, and the name its problem is found by. */
  id: string;
  legend: TemplateResult;
  input: TemplateResult;
  /** What is wrong with the answer, said under it; '' when nothing is. */
  problem: string;
}

export function questionCard({ id, legend, input, problem }: QuestionCard): TemplateResult {
  const problemId = `${id}-problem`;
  return html`<fieldset data-question=${id} aria-invalid=${problem ? 'true' : 'false'} aria-describedby=${problem ? problemId : nothing}>
    <legend>${legend}</legend>
    ${input} ${problem ? html`<p class="problem" id=${problemId}>${problem}</p>` : nothing}
  </fieldset>`;
}

/** "Hand in", and `problems` (how many answers still need attention, said as an alert) when there are any. */
export function handInRow(problems: number, say: (count: number) => string): TemplateResult {
  return html`<div class="actions">
    <button class="primary" type="submit">${msg('Hand in')}</button>
    ${problems > 0 ? html`<span class="problem" role="alert">${say(problems)}</span>` : nothing}
  </div>`;
}

/** Puts the focus on the first field of the question `id`, once the page shows its problem. */
export async function focusQuestion(element: { renderRoot: ParentNode; updateComplete: Promise<unknown> }, id: string): Promise<void> {
  await element.updateComplete;
  element.renderRoot.querySelector<HTMLElement>(`[data-question="${id}"] :is(input, textarea)`)?.focus();
}
