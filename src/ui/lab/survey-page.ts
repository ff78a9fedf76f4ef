import { msg } from '@lit/localize';
import { html, nothing, type TemplateResult } from 'lit';
import type { Assignment } from '../../classroom/assignment.ts';
import type { SurveySubmission } from '../../classroom/survey-answers.ts';
import type { QuestController } from './quest-controller.ts';

/** The id of the assignment's closing survey when it is due (every level passed, not handed in yet), else null. */
function surveyDue(game: QuestController, assignment: Assignment | null): string | null {
  const surveyId = assignment?.survey;
  // The concept test after the levels comes first (concept-test-page.ts).
  return surveyId && game.session?.allPassed && !game.survey && !game.session.conceptTests.due && customElements.get('rt-survey-page') ? surveyId : null;
}

/**
 * The closing survey on its own page over the lab (placed as the level map is), once it is
 * due and until the learner hands it in or puts it off. The lab leaves it out while the
 * render window is open: the last task is often a render, whose image comes first.
 */
export function surveyPage(game: QuestController, assignment: Assignment | null): TemplateResult | typeof nothing {
  const surveyId = surveyDue(game, assignment);
  if (!surveyId || game.surveyLater) return nothing;
  return html`<rt-survey-page
    survey-id=${surveyId}
    locale=${game.session?.locale ?? 'en'}
    .levels=${assignment?.levels ?? null}
    .choice=${assignment?.surveyQuestions}
    @survey-later=${() => game.putSurveyOff(true)}
    @survey-submitted=${(event: CustomEvent<SurveySubmission>) => game.surveySubmitted(event.detail)}
  ></rt-survey-page>`;
}

/** At the top of the task column while the survey is due: what it is, and the button that opens its page. */
export function surveyWaiting(game: QuestController, assignment: Assignment | null): TemplateResult | typeof nothing {
  if (!surveyDue(game, assignment)) return nothing;
  return html`<div class="welcome">
    <p><strong>${msg('One more thing: the closing survey')}</strong></p>
    <p>${msg('Your teacher asks a few questions about the game. Your answers go with your results.')}</p>
    <button data-command="survey-open" @click=${() => game.putSurveyOff(false)}>${msg('Answer the questions')}</button>
  </div>`;
}
