import { msg, str } from '@lit/localize';
import { ContextConsumer } from '@lit/context';
import { css, html, nothing, type PropertyValues } from 'lit';
import { MATCH_SCORE, matchScore } from '../../quest/challenge-closeness.ts';
import { challengeStars, starText, type ChallengeCounts, type Stars } from '../../quest/challenge-par.ts';
import type { ChallengeGoal } from '../../quest/goal.ts';
import type { Locale } from '../../quest/localized-text.ts';
import { LocalizedElement } from '../controls/localized-element.ts';
import { challengePicturesContext, type ChallengeView } from './challenge-pictures.ts';
import { rayCount, starRuleText } from './challenge-rule-text.ts';
import { gameStyles, taskPanelStyles } from './game-styles.ts';

/**
 * @summary The challenge panel of a match-the-target task (spec/challenges.md §2): a meter of
 * the difference as a match score with the match line marked, the target picture beside the
 * learner's last render and their difference, the star rule (open before the first render,
 * folded after it so that the pictures and the meter fit a 768-pixel-high screen) and the
 * renders, changes and rays counted. The lab's referee
 * (challengePicturesContext) renders and measures; this element only shows. Once the task is
 * done it shows only the stars, the saved ones when the learner comes back to the level.
 */
export class RtChallenge extends LocalizedElement {
  static override properties = { goal: { attribute: false }, locale: {}, summary: { type: Boolean }, stars: { type: Number }, view: { state: true } };
  static override styles = [
    gameStyles,
    taskPanelStyles,
    css`
      p {
        margin: 4px 0;
      }
      .pictures {
        display: grid;
        grid-template-columns: 1fr 1fr;
        gap: 6px;
        margin: 8px 0;
      }
      figure {
        margin: 0;
        min-width: 0;
      }
      /* The target is what the learner studies most: the whole width. */
      figure:first-child {
        grid-column: 1 / -1;
      }
      figcaption {
        font-size: 0.75rem;
      }
      canvas {
        width: 100%;
        aspect-ratio: 4 / 3;
        image-rendering: pixelated;
        border: 1px solid var(--rt-border);
        background: var(--rt-surface);
      }
      .meter {
        position: relative;
      }
      meter {
        width: 100%;
        height: 18px;
      }
      /* The threshold, where the meter's fill must reach. */
      .mark {
        position: absolute;
        top: 0;
        bottom: 0;
        width: 2px;
        background: var(--rt-text, currentColor);
      }
      .stars {
        font-weight: 600;
      }
      summary {
        cursor: pointer;
        font-size: 0.875rem;
      }
    `,
  ];

  declare goal: ChallengeGoal | null;
  declare locale: Locale;
  /** Once the task is done: only the stars the match earned (the panel itself has served). */
  declare summary: boolean;
  /** The stars saved with the learner's progress for this challenge; null when none were earned (or not yet). */
  declare stars: Stars | null;
  declare private view: ChallengeView | null;
  private readonly referee = new ContextConsumer(this, { context: challengePicturesContext, subscribe: true });
  private stop: (() => void) | null = null;
  private watched: ChallengeGoal | null = null;

  constructor() {
    super();
    this.goal = null;
    this.locale = 'en';
    this.summary = false;
    this.stars = null;
    this.view = null;
  }

  override disconnectedCallback(): void {
    super.disconnectedCallback();
    this.unwatch();
  }

  protected override willUpdate(): void {
    const referee = this.referee.value;
    if (this.goal === this.watched && (this.stop || !referee)) return;
    this.unwatch();
    this.watched = this.goal;
    if (this.goal && referee) this.stop = referee.watch(this.goal, (view) => (this.view = view));
  }

  private unwatch(): void {
    this.stop?.();
    this.stop = null;
    this.watched = null;
  }

  override render() {
    const goal = this.goal;
    if (!goal) return nothing;
    const { threshold } = goal.challenge.measure;
    const [width, height] = goal.challenge.measure.size;
    const view = this.view;
    const score = view?.value === null || !view ? null : matchScore(view.value, threshold);
    if (this.summary) return this.earned(goal, view?.matched ?? null);
    return html`
      <section class="card" aria-labelledby="challenge-title">
        <h3 id="challenge-title">${msg('Challenge')}</h3>
        <div class="meter">
          <meter aria-label=${msg('Match score')} min="0" max="100" low=${MATCH_SCORE} optimum="100" value=${score ?? 0}></meter>
          <span class="mark" style="left: ${MATCH_SCORE}%" aria-hidden="true"></span>
        </div>
        <p aria-live="polite">
          ${view?.measuring ? msg('Comparing your render with the target…') : score === null ? msg('Render to compare with the target.') : msg(str`Match score: ${score} of 100 (a match: ${MATCH_SCORE} or more).`)}
        </p>
        <div class="pictures">
          ${this.picture('target', msg('Target'))} ${this.picture('attempt', msg('Your last render'))}
          ${this.picture('difference', msg('Difference (brighter: further off)'))}
        </div>
        <details ?open=${(view?.renders ?? 0) === 0}>
          <summary>${msg('How it is scored')}</summary>
          <p>${msg(str`Match the target: a match score of ${MATCH_SCORE} or more, measured on ${width} × ${height} pixels.`)}</p>
          <p>
            ${msg("The score compares each pixel's red, green and blue with the target's: 100 means (almost) the same picture, and each time your render gets ten times closer, the score goes up by 25.")}
          </p>
          <p>${starRuleText(goal.challenge.par, this.locale)}</p>
          <p>${msg('Only the settings shown in the panels can change; everything else in this scene is locked.')}</p>
        </details>
        <p>${this.countsText(view)}</p>
        ${view?.matched ? this.earned(goal, view.matched) : nothing}
      </section>
    `;
  }

  /** The stars of a match: this visit's, with what it took, else the saved ones. */
  private earned(goal: ChallengeGoal, matched: ChallengeCounts | null) {
    if (matched) {
      const stars = starText(challengeStars(matched, goal.challenge.par));
      return html`<p class="stars">${msg(str`Matched (renders: ${matched.renders} · changes: ${matched.changes}): ${stars}`)}</p>`;
    }
    return this.stars ? html`<p class="stars">${msg(str`Stars earned: ${starText(this.stars)}`)}</p>` : nothing;
  }

  private countsText(view: ChallengeView | null): string {
    const renders = view?.renders ?? 0;
    const changes = view?.changes ?? 0;
    if (this.goal?.challenge.par.kind !== 'rays') return msg(str`Renders: ${renders} · changes: ${changes}`);
    return msg(str`Renders: ${renders} · changes: ${changes} · rays: ${rayCount(view?.rays ?? 0, this.locale)}`);
  }

  private picture(which: 'target' | 'attempt' | 'difference', caption: string) {
    const [width, height] = this.goal?.challenge.measure.size ?? [64, 48];
    return html`<figure>
      <canvas data-picture=${which} width=${width} height=${height} role="img" aria-label=${caption}></canvas>
      <figcaption>${caption}</figcaption>
    </figure>`;
  }

  protected override updated(changed: PropertyValues): void {
    super.updated(changed);
    for (const canvas of this.renderRoot.querySelectorAll<HTMLCanvasElement>('canvas[data-picture]')) {
      const image = this.view?.[canvas.dataset.picture as 'target' | 'attempt' | 'difference'] ?? null;
      const context = canvas.getContext('2d');
      if (!context) continue;
      if (image) context.putImageData(image, 0, 0);
      else context.clearRect(0, 0, canvas.width, canvas.height);
    }
  }
}

customElements.define('rt-challenge', RtChallenge);

declare global {
  interface HTMLElementTagNameMap {
    'rt-challenge': RtChallenge;
  }
}
