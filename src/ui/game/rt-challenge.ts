import { msg, str } from '@lit/localize';
import { ContextConsumer } from '@lit/context';
import { css, html, nothing, type PropertyValues } from 'lit';
import { challengeStars } from '../../quest/challenge-closeness.ts';
import type { ChallengeGoal } from '../../quest/goal.ts';
import type { Locale } from '../../quest/localized-text.ts';
import { LocalizedElement } from '../controls/localized-element.ts';
import { challengePicturesContext, type ChallengeView } from './challenge-pictures.ts';
import { gameStyles } from './game-styles.ts';

/**
 * @summary The challenge panel of a match-the-target task (spec/challenges.md §2): the
 * target picture beside the learner's last render and their difference, a meter of the
 * difference with the match threshold marked, the star rule (shown before the first render)
 * and the renders and changes counted. The lab's referee (challengePicturesContext) renders
 * and measures; this element only shows.
 */
export class RtChallenge extends LocalizedElement {
  static override properties = { goal: { attribute: false }, locale: {}, summary: { type: Boolean }, view: { state: true } };
  static override styles = [
    gameStyles,
    css`
      :host {
        display: block;
        margin: 8px 0;
      }
      h3 {
        margin: 0 0 6px;
        font-size: 1rem;
      }
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
    `,
  ];

  declare goal: ChallengeGoal | null;
  declare locale: Locale;
  /** Once the task is done: only the stars the match earned (the panel itself has served). */
  declare summary: boolean;
  declare private view: ChallengeView | null;
  private readonly referee = new ContextConsumer(this, { context: challengePicturesContext, subscribe: true });
  private stop: (() => void) | null = null;
  private watched: ChallengeGoal | null = null;

  constructor() {
    super();
    this.goal = null;
    this.locale = 'en';
    this.summary = false;
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
    const par = goal.challenge.par.renders;
    const view = this.view;
    const number = (value: number) => new Intl.NumberFormat(this.locale, { maximumSignificantDigits: 2 }).format(value);
    const limit = number(threshold);
    const stars =
      view && view.matchedAfter !== null
        ? html`<p class="stars">${msg(str`Matched after ${view.matchedAfter} renders: ${'★'.repeat(challengeStars(view.matchedAfter, par))}`)}</p>`
        : nothing;
    if (this.summary) return stars;
    return html`
      <section class="card" aria-labelledby="challenge-title">
        <h3 id="challenge-title">${msg('Challenge')}</h3>
        <p>${msg(str`Match the target: a difference of ${limit} or less, measured on ${width} × ${height} pixels.`)}</p>
        <p>${msg(str`Stars: ★★★ within ${par} renders, ★★ within ${Math.floor(par * 1.5)}, ★ for any match.`)}</p>
        <p>${msg('Only the settings shown in the panels can change; everything else in this scene is locked.')}</p>
        <div class="pictures">
          ${this.picture('target', msg('Target'))} ${this.picture('attempt', msg('Your last render'))}
          ${this.picture('difference', msg('Difference (brighter: further off)'))}
        </div>
        <div class="meter">
          <meter
            aria-label=${msg('Closeness to the target')}
            min="0"
            max="1"
            low=${MARK}
            optimum="1"
            value=${view?.value === null || !view ? 0 : closeness(view.value, threshold)}
          ></meter>
          <span class="mark" style="left: ${MARK * 100}%" aria-hidden="true"></span>
        </div>
        <p aria-live="polite">
          ${view?.measuring ? msg('Comparing your render with the target…') : view?.value === null || !view ? msg('Render to compare with the target.') : msg(str`Difference: ${number(view.value)} (match: ${limit} or less).`)}
        </p>
        <p>${msg(str`Renders: ${view?.renders ?? 0} · changes: ${view?.changes ?? 0}`)}</p>
        ${stars}
      </section>
    `;
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

/** Where the threshold sits on the meter: two thirds of the way, so a near miss still shows progress. */
const MARK = 2 / 3;

/**
 * The meter's fill for a difference: on a log scale, from a hundred times the threshold
 * (empty) to a tenth of it (full), so that each tenfold step closer moves it a third.
 */
export function closeness(difference: number, threshold: number): number {
  if (difference <= 0) return 1;
  const decades = Math.log10(difference / threshold);
  return Math.min(1, Math.max(0, MARK - decades / 3));
}

customElements.define('rt-challenge', RtChallenge);

declare global {
  interface HTMLElementTagNameMap {
    'rt-challenge': RtChallenge;
  }
}
