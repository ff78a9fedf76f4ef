import { msg, str } from '@lit/localize';
import { html, nothing, type TemplateResult } from 'lit';
import { conceptForms } from '../../classroom/concept-test/concept-test-plan.ts';
import { saveProblemReason } from '../../i18n/progress-problem-text.ts';
import type { ConceptTestHandIn } from '../classroom/rt-concept-test.ts';
import type { QuestController } from './quest-controller.ts';

/**
 * The assignment's concept test over the lab while one is due (QuestSession.conceptTests.due):
 * the one before after the participant code, the one after before the closing survey. The
 * form follows from the assignment's order and the playthrough's attempt id
 * (concept-test-plan.ts). Answers that storage refuses are kept in memory and said so, as
 * the survey's are.
 */
export function conceptTestPage(game: QuestController, toast: (text: string, tone: 'info' | 'error') => void): TemplateResult | typeof nothing {
  const session = game.session;
  const phase = session?.conceptTests.due;
  const order = session?.assignment?.conceptTest;
  if (!session || !phase || !order || session.needsParticipantCode) return nothing;
  const seed = session.context.attemptId ?? '';
  const handIn = ({ detail }: CustomEvent<ConceptTestHandIn>) => {
    const problem = session.conceptTests.submit(detail.phase, detail.submission);
    if (problem)
      toast(
        msg(
          str`Your answers could not be saved in the browser: ${saveProblemReason(problem)}. They are kept while this page is open: download your data for your teacher before you close it.`,
        ),
        'error',
      );
    else toast(detail.phase === 'pre' ? msg('Thank you! Now the game begins.') : msg('Thank you! Your answers are saved.'), 'info');
    // The closing survey comes next (after the test after), not put off.
    game.putSurveyOff(false);
  };
  return html`<rt-concept-test
    phase=${phase}
    form=${conceptForms(order, seed)[phase]}
    seed=${seed}
    locale=${session.locale}
    @concept-test-submitted=${handIn}
  ></rt-concept-test>`;
}
