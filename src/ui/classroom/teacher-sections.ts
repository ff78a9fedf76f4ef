import { msg } from '@lit/localize';
import { html, nothing } from 'lit';
import type { Assignment } from '../../classroom/assignment.ts';
import { surveyAsked } from '../../classroom/survey-for-levels.ts';
import { surveyPreviewHash } from '../../classroom/survey-preview-link.ts';
import { SURVEY_IDS, surveyById } from '../../classroom/surveys.ts';
import { surveyQuestionsSection } from './teacher-survey-questions.ts';

/**
 * Sections of the teacher page (rt-teacher-page.ts), each a function of the assignment and
 * of `change`, which takes the fields a section changes. A new section is such a function
 * (in a file of its own when it is more than a few lines), added with one line to the page.
 */

/** Changes some fields of the assignment the page shows. */
export type ChangeAssignment = (changes: Partial<Assignment>) => void;

/** How the game starts and ends for the students: other levels, language, participant code, survey and its questions. */
export function settingsSection(a: Assignment, change: ChangeAssignment) {
  return html`<section>
    <h2>${msg('Settings')}</h2>
    ${choice(change, msg('Other levels'), 'otherLevels', a.otherLevels, [
      ['hidden', msg('Hidden: only the assignment')],
      ['shown', msg('Shown: playable after the assignment')],
    ])}
    ${choice(change, msg('Language'), 'locale', a.locale, [
      ['en', 'English'],
      ['nl', 'Nederlands'],
    ])}
    ${choice(change, msg('Participant code'), 'askParticipantCode', a.askParticipantCode ? 'yes' : 'no', [
      ['no', msg('Do not ask')],
      ['yes', msg('Ask for a code at the start (for research)')],
    ])}
    ${choice(change, msg('Closing survey'), 'survey', a.survey ?? 'none', [
      ['none', msg('None')],
      ...SURVEY_IDS.map((id): [string, string] => [id, id === 'default' ? msg('The standard questions (about 5 minutes)') : id]),
    ])}
    ${a.survey ? html`<a href=${surveyPreview(a.survey, a)} target="_blank" rel="noopener">${msg('Preview the survey (opens a new tab)')}</a>` : nothing}
    ${surveyQuestionsSection(a, change)}
  </section>`;
}

/** The preview's address: the survey with the questions this assignment asks. */
function surveyPreview(surveyId: string, a: Assignment): string {
  const survey = surveyById(surveyId);
  return surveyPreviewHash(surveyId, survey ? surveyAsked(survey, a.levels, a.surveyQuestions).questions.map((question) => question.id) : []);
}

/** The class code and the school's address: what the dashboard and xAPI need. */
export function researchSection(a: Assignment, change: ChangeAssignment) {
  return html`<section>
    <h2>${msg('For the dashboard and research (optional)')}</h2>
    <label class="field">
      ${msg('Class code (the dashboard can show one class)')}
      <input type="text" name="class-code" maxlength="32" placeholder="3B" .value=${a.classCode ?? ''} @input=${(e: Event) => change({ classCode: optional((e.target as HTMLInputElement).value) })} />
    </label>
    <label class="field">
      ${msg("Your school's web address, for xAPI accounts")}
      <input
        type="url"
        name="xapi-home-page"
        maxlength="200"
        placeholder="https://school.example"
        .value=${a.xapiHomePage ?? ''}
        @input=${(e: Event) => change({ xapiHomePage: optional((e.target as HTMLInputElement).value) })}
      />
    </label>
    <p class="muted">${msg('With a learning record store shared by schools, this keeps code "P-07" of your school apart from another school\'s.')}</p>
  </section>`;
}

/** The way to the dashboard, for the files the students hand in. */
export function afterLessonSection() {
  return html`<section aria-labelledby="after-heading">
    <h2 id="after-heading">${msg('After the lesson')}</h2>
    <p><a class="button" href="#/dashboard" target="_blank" rel="noopener">${msg('Open the dashboard')}</a></p>
    <p class="muted">${msg("Drop the students' result files on the dashboard: times per level and task, where they got stuck, and the survey. Nothing is uploaded.")}</p>
  </section>`;
}

function choice(
  change: ChangeAssignment,
  legend: string,
  name: 'otherLevels' | 'locale' | 'askParticipantCode' | 'survey',
  value: string,
  options: [string, string][],
) {
  const pick = (option: string) => {
    if (name === 'askParticipantCode') change({ askParticipantCode: option === 'yes' });
    else if (name === 'survey') change({ survey: option === 'none' ? null : option });
    else if (name === 'locale') change({ locale: option === 'nl' ? 'nl' : 'en' });
    else change({ otherLevels: option === 'shown' ? 'shown' : 'hidden' });
  };
  return html`<fieldset class="choices">
    <legend>${legend}</legend>
    ${options.map(
      ([option, label]) => html`<label class="check">
        <input type="radio" name=${name} value=${option} .checked=${value === option} @change=${() => pick(option)} />
        ${label}
      </label>`,
    )}
  </fieldset>`;
}

/** A typed optional field: trimmed, undefined when empty (left out of the link). */
export function optional(text: string): string | undefined {
  return text.trim() === '' ? undefined : text.trim();
}
