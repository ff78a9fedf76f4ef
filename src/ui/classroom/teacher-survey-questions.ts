import { msg } from '@lit/localize';
import { html, nothing } from 'lit';
import type { Assignment } from '../../classroom/assignment.ts';
import { fitsLevels, isAsked } from '../../classroom/survey-for-levels.ts';
import { surveyById } from '../../classroom/surveys.ts';
import { localize } from '../../quest/localized-text.ts';
import type { ChangeAssignment } from './teacher-sections.ts';

/**
 * The closing survey's questions on the teacher page, each with a box to ask it or not.
 * Ticked at first are those that fit the assignment's levels (survey-for-levels.ts); a box
 * the teacher changes is kept in the assignment (Assignment.surveyQuestions) only while it
 * differs from that default, so the choice follows the levels wherever the teacher made none.
 */
export function surveyQuestionsSection(a: Assignment, change: ChangeAssignment) {
  const survey = a.survey === null ? undefined : surveyById(a.survey);
  if (!survey) return nothing;
  const toggle = (id: string, fits: boolean, asked: boolean) => {
    const { [id]: _old, ...others } = a.surveyQuestions ?? {};
    const choice = asked === fits ? others : { ...others, [id]: asked };
    change({ surveyQuestions: Object.keys(choice).length > 0 ? choice : undefined });
  };
  return html`<fieldset class="survey-questions">
    <legend>${msg('Survey questions to ask')}</legend>
    <p class="muted">${msg('Ticked at first: the questions that fit the chosen levels. Tick any question on or off to choose yourself.')}</p>
    ${survey.questions.map((question) => {
      const fits = fitsLevels(question, a.levels);
      return html`<label class="check">
        <input
          type="checkbox"
          name=${`survey/${question.id}`}
          .checked=${isAsked(question, a.levels, a.surveyQuestions)}
          @change=${(e: Event) => toggle(question.id, fits, (e.target as HTMLInputElement).checked)}
        />
        ${localize(question.text, a.locale)} ${fits ? nothing : html`<span class="muted">${msg('(about levels not in the assignment)')}</span>`}
      </label>`;
    })}
    <button type="button" ?disabled=${!a.surveyQuestions} @click=${() => change({ surveyQuestions: undefined })}>${msg('Back to the questions that fit the levels')}</button>
  </fieldset>`;
}

/** Whether the assignment has a survey but asks none of its questions: the page asks for one, or no survey. */
export function asksNoSurveyQuestion(a: Assignment): boolean {
  const survey = a.survey === null ? undefined : surveyById(a.survey);
  return !!survey && survey.questions.every((question) => !isAsked(question, a.levels, a.surveyQuestions));
}
