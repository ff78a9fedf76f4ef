import { msg } from '@lit/localize';
import { html, nothing, type TemplateResult } from 'lit';
import type { Assignment } from '../../classroom/assignment.ts';
import { badgeName, badgeOfLevel } from '../game/badge-names.ts';
import type { QuestController } from './quest-controller.ts';
import { surveyWaiting } from './survey-page.ts';

/**
 * The lab's right-hand column: the level's tasks (with a newcomer's welcome), or what the
 * free lab and the map are for, under the closing survey's button once an assignment is
 * passed (its page: survey-page.ts); at the bottom the learner's data for their teacher.
 */
export function taskColumn(game: QuestController, assignment: Assignment | null, toast: (text: string, tone: 'error') => void): TemplateResult {
  return html`${tasks(game, assignment)}${yourData(game, assignment, toast)}`;
}

/** The level's tasks, or what the free lab and the map are for; over them, the closing survey while it waits. */
function tasks(game: QuestController, assignment: Assignment | null) {
  return html`${surveyWaiting(game, assignment)}${modeTasks(game, assignment)}`;
}

function modeTasks(game: QuestController, assignment: Assignment | null) {
  const session = game.session;
  const view = session?.mode.kind === 'level' ? session.engine.level : null;
  if (session?.mode.kind === 'free-lab') {
    return html`<h2>${msg('Free lab')}</h2>
      <p>${msg('Build and explore your own scene: every panel is here, and your scene is kept for next time.')}</p>
      <button class="primary" @click=${() => session.openMap()}>${msg('Level map')}</button>`;
  }
  if (session?.mode.kind === 'finished') {
    return html`<rt-assignment-done heading=${assignment?.title ?? ''} @open-map=${() => session.openMap()}></rt-assignment-done>`;
  }
  if (!session || !view) {
    return html`<p>${msg('Your tasks appear here when you play a level. In the free lab, explore freely.')}</p>
      <button class="primary" @click=${() => session?.openMap()}>${msg('Level map')}</button>`;
  }
  const { level } = view;
  const earned = session.engine.badges.filter((earnedBadge) => badgeOfLevel(earnedBadge.badge, level.id, level.chapter));
  return html`
    ${
      game.welcome
        ? html`<div class="welcome" role="status">
          <p><strong>${msg('Welcome to Ray Tracer Quest!')}</strong></p>
          <p>${msg('Do the tasks below, one at a time. Stuck? Press "Hint". The Levels button shows all levels.')}</p>
          <button @click=${() => game.dismissWelcome()}>${msg('Got it')}</button>
        </div>`
        : nothing
    }
    <rt-quest-panel
      .view=${view}
      locale=${session.locale}
      ?has-next-level=${session.nextLevel() !== undefined}
      .badges=${earned.map((earnedBadge) => badgeName(earnedBadge.badge, session.catalog, session.locale))}
    ></rt-quest-panel>
  `;
}

/** Downloads of the learner's own timings (CSV, JSON, xAPI) for their teacher. */
function yourData(game: QuestController, assignment: Assignment | null, toast: (text: string, tone: 'error') => void) {
  const session = game.session;
  if (!session) return nothing;
  return html`<section class="your-data" aria-label=${msg('Your data')}>
    <h2>${msg('Your data for your teacher')}</h2>
    <rt-export-menu
      .progress=${() => session.engine.progress}
      .participant=${session.context.participantCode}
      .attemptId=${session.context.attemptId}
      .assignment=${assignment}
      .survey=${game.survey}
      .conceptTest=${session.conceptTests.answers}
      @export-failed=${(event: CustomEvent<string>) => toast(event.detail, 'error')}
    ></rt-export-menu>
  </section>`;
}
