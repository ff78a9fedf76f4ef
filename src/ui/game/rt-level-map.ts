import { msg, str } from '@lit/localize';
import { issueText } from '../../i18n/issue-text.ts';
import { css, html, nothing, type TemplateResult } from 'lit';
import { LocalizedElement } from '../controls/localized-element.ts';
import type { LevelMapEntry, ChapterMapView } from '../../quest/level-map.ts';
import { localize, type Locale } from '../../quest/localized-text.ts';
import { plainLevelText } from '../../quest/text-markup.ts';
import { starText } from '../../quest/challenge-par.ts';
import { FocusReturn } from '../controls/focus-return.ts';
import { fire, gameStyles } from './game-styles.ts';

/** The detail of `map-choice`: a level to play, the free lab, or back to the open level. */
export type MapChoice = { kind: 'level'; id: string } | { kind: 'free-lab' } | { kind: 'close' };

/**
 * @summary The level map: chapters with their levels, each marked passed (✓), open,
 * locked (×, with what opens it in its tooltip) or broken (⚠, with the file's problems), its points,
 * a matched challenge's stars (★★☆), and the level the learner is in. Also the way into the free lab.
 *
 * @fires map-choice - CustomEvent<MapChoice>.
 */
export class RtLevelMap extends LocalizedElement {
  static override properties = {
    chapters: { attribute: false },
    locale: {},
    current: {},
    welcome: { type: Boolean },
    closable: { type: Boolean },
    heading: {},
  };
  static override styles = [
    gameStyles,
    css`
      :host {
        display: block;
        overflow-y: auto;
        padding: 16px 24px;
        background: var(--rt-bg);
      }
      .top {
        display: flex;
        align-items: center;
        gap: 12px;
        flex-wrap: wrap;
        margin-bottom: 12px;
      }
      h2 {
        margin: 0 auto 0 0;
        font-size: 1.3rem;
      }
      section {
        margin-bottom: 16px;
      }
      h3 {
        font-size: 1rem;
        color: var(--rt-muted);
      }
      ol {
        display: grid;
        grid-template-columns: repeat(auto-fill, minmax(220px, 1fr));
        gap: 10px;
        margin: 0;
        padding: 0;
        list-style: none;
      }
      .level {
        box-sizing: border-box;
        display: flex;
        flex-direction: column;
        align-items: flex-start;
        gap: 4px;
        width: 100%;
        min-height: 88px;
        padding: 10px 12px;
        text-align: left;
        border-radius: var(--rt-radius);
      }
      .level strong {
        font-size: 0.95rem;
      }
      .level[data-status='passed'] {
        border-color: var(--rt-success);
      }
      .level[data-current] {
        border: 2px solid var(--rt-accent);
      }
      /* Locked says so in words too; the dashed, flat card lets the open ones stand out. */
      .level[data-status='locked'] {
        border-style: dashed;
        background: var(--rt-surface-2);
        cursor: not-allowed;
      }
      .level[data-status='broken'] {
        border-color: var(--rt-danger);
        cursor: default;
      }
      .status {
        font-size: 0.8125rem;
        color: var(--rt-muted);
      }
      [data-status='passed'] .status {
        color: var(--rt-success);
      }
      [data-status='broken'] .status {
        color: var(--rt-danger);
      }
      /* A challenge's golf score (★★☆): the learner's own, shown only to them. */
      .stars {
        font-size: 0.875rem;
        letter-spacing: 1px;
      }
      .reasons {
        margin: 4px 0 0;
        padding-left: 1.2em;
        font-size: 0.75rem;
        color: var(--rt-muted);
        overflow-wrap: anywhere;
      }
      .welcome {
        margin-bottom: 16px;
        max-width: 60ch;
      }
    `,
  ];

  declare chapters: ChapterMapView[];
  declare locale: Locale;
  /** The level the learner is in (resume), if any. */
  declare current: string | null;
  declare welcome: boolean;
  /** Whether there is an open level to go back to. */
  declare closable: boolean;
  /** An assignment's title instead of "Levels". */
  declare heading: string;

  private readonly focusReturn = new FocusReturn();

  constructor() {
    super();
    this.addEventListener('keydown', (event) => {
      if (event.key === 'Escape' && this.closable) fire(this, 'map-choice', { kind: 'close' } satisfies MapChoice);
    });
    this.chapters = [];
    this.locale = 'en';
    this.current = null;
    this.welcome = false;
    this.closable = false;
    this.heading = '';
  }

  override connectedCallback(): void {
    super.connectedCallback();
    this.focusReturn.remember();
  }

  override disconnectedCallback(): void {
    super.disconnectedCallback();
    this.focusReturn.restore(this);
  }

  /** The map covers the lab: the focus goes to the level to continue (else the first one to play), not behind the map. */
  protected override firstUpdated(): void {
    const levels =
      this.renderRoot.querySelector<HTMLElement>('.level[data-current]') ?? this.renderRoot.querySelector<HTMLElement>('.level[aria-disabled="false"]');
    levels?.focus();
  }

  override render() {
    const choose = (choice: MapChoice) => fire(this, 'map-choice', choice);
    return html`
      <div class="top">
        <h2 id="map-title">${this.heading || msg('Levels')}</h2>
        <button @click=${() => choose({ kind: 'free-lab' })} title=${msg('Build and explore your own scene with every panel')}>${msg('Free lab')}</button>
        ${this.closable ? html`<button class="primary" @click=${() => choose({ kind: 'close' })}>${msg('Back to the level')}</button>` : nothing}
      </div>
      ${
        this.welcome
          ? html`<p class="welcome">${msg('Welcome to Ray Tracer Quest! Each level teaches one idea about ray tracing. Start with the first level; the next one opens when you finish its tasks.')}</p>`
          : nothing
      }
      ${this.chapters.map((chapter, chapterIndex) => {
        // Levels are numbered through the whole curriculum (level 3 is "3." in its chapter too).
        const first = this.chapters.slice(0, chapterIndex).reduce((count, earlier) => count + earlier.levels.length, 1);
        return html`<section aria-labelledby=${`chapter-${chapter.id}`}>
          <h3 id=${`chapter-${chapter.id}`}>${localize(chapter.title, this.locale)}</h3>
          <ol start=${first}>
            ${chapter.levels.map((entry, index) => html`<li>${this.entry(entry, first + index, choose)}</li>`)}
          </ol>
        </section>`;
      })}
    `;
  }

  private entry(entry: LevelMapEntry, number: number, choose: (choice: MapChoice) => void): TemplateResult {
    const title = entry.level ? plainLevelText(entry.level.title, this.locale) : entry.id;
    const current = entry.id === this.current;
    const playable = entry.status === 'open' || entry.status === 'passed';
    return html`<button
      class="level"
      data-level=${entry.id}
      data-status=${entry.status}
      ?data-current=${current}
      aria-disabled=${String(!playable)}
      title=${this.tooltip(entry)}
      @click=${() => playable && choose({ kind: 'level', id: entry.id })}
    >
      <strong>${number}. ${title}</strong>
      <span class="status">${this.statusText(entry, current)}</span>
      ${entry.stars ? html`<span class="stars" role="img" aria-label=${msg(str`Challenge: ${entry.stars} of 3 stars`)}>${starText(entry.stars)}</span>` : nothing}
      ${
        entry.status === 'broken'
          ? html`<ul class="reasons">
            ${entry.errors.slice(0, 4).map((error) => html`<li>${issueText(error)}</li>`)}
          </ul>`
          : nothing
      }
    </button>`;
  }

  private statusText(entry: LevelMapEntry, current: boolean): string {
    const points = msg(str`${entry.points} / ${entry.maxPoints} pts`);
    switch (entry.status) {
      case 'passed':
        return `✓ ${msg('Passed')} · ${points}`;
      case 'open':
        return current ? `▶ ${msg('Continue')} · ${points}` : `○ ${msg('Open')} · ${points}`;
      case 'locked':
        return `× ${msg('Locked')}`;
      case 'broken':
        return `⚠ ${msg('This level could not be loaded:')}`;
    }
  }

  private tooltip(entry: LevelMapEntry): string {
    switch (entry.status) {
      case 'locked':
        return msg('Finish the tasks of the levels before this one to open it');
      case 'broken':
        return msg('The level file has problems (listed here); the other levels still play');
      default:
        return msg('Play this level');
    }
  }
}

customElements.define('rt-level-map', RtLevelMap);

declare global {
  interface HTMLElementTagNameMap {
    'rt-level-map': RtLevelMap;
  }
}
