import { msg, str } from '@lit/localize';
import { html, nothing } from 'lit';
import { reachedMatch, summarizeChallenges } from '../../../classroom/dashboard-challenges.ts';
import { MATCH_SCORE } from '../../../quest/challenge-closeness.ts';
import { LevelTableElement } from './level-table-element.ts';
import { namedRowsTableStyles, tableStyles } from './rt-dashboard-chart-styles.ts';

/**
 * @summary How close the class got in a level's challenges (classroom/dashboard-challenges.ts):
 * per challenge the learners who rendered, each one's best match score (lowest first), who
 * matched it themselves with how many stars, and the last score of those who stopped
 * without a match. Nothing when the level has no challenge anyone rendered in.
 */
export class RtDashboardChallenges extends LevelTableElement {
  static override styles = [tableStyles, namedRowsTableStyles];

  override render() {
    const challenges = summarizeChallenges(this.records).filter((challenge) => challenge.level === this.level);
    if (challenges.length === 0) return nothing;
    const list = (scores: readonly number[]) => (scores.length === 0 ? '–' : scores.join(', '));
    return html`<h3>${msg('Challenges')}</h3>
      <table>
        <caption>
          ${msg(str`How close students got to each challenge's target: a match score of ${MATCH_SCORE} or more is a match`)}
        </caption>
        <thead>
          <tr>
            <th scope="col">${msg('Task')}</th>
            <th scope="col" title=${msg('Students who rendered at least once')}>n</th>
            <th scope="col">${msg('Best match score per student')}</th>
            <th scope="col">${msg('Matched by themselves (★ / ★★ / ★★★)')}</th>
            <th scope="col">${msg('Stopped without a match, at')}</th>
          </tr>
        </thead>
        <tbody>
          ${challenges.map(
            (challenge) =>
              html`<tr data-task=${challenge.task}>
                <th scope="row">${this.taskName(challenge.task)}</th>
                <td>${challenge.learners}</td>
                <td>${list(challenge.bestScores)} (${msg(str`${reachedMatch(challenge)} reached ${MATCH_SCORE}`)})</td>
                <td>${challenge.matched} (${challenge.stars.join(' / ')})</td>
                <td>${list(challenge.stoppedAt)}</td>
              </tr>`,
          )}
        </tbody>
      </table>`;
  }
}

customElements.define('rt-dashboard-challenges', RtDashboardChallenges);

declare global {
  interface HTMLElementTagNameMap {
    'rt-dashboard-challenges': RtDashboardChallenges;
  }
}
