import { msg, str } from '@lit/localize';
import { css, html } from 'lit';
import { LocalizedElement } from '../controls/localized-element.ts';
import { gameStyles } from './game-styles.ts';

/**
 * @summary The learner's score in the header: points and a badge count; the button opens
 * a popover listing the badges by name.
 */
export class RtScore extends LocalizedElement {
  static override properties = { points: { type: Number }, badges: { attribute: false } };
  static override styles = [
    gameStyles,
    css`
      :host {
        position: relative;
      }
      button {
        display: inline-flex;
        align-items: center;
        gap: 10px;
        font-variant-numeric: tabular-nums;
      }
      [popover] {
        min-width: 220px;
        max-width: 320px;
      }
      ul {
        margin: 0;
        padding-left: 1.2em;
      }
    `,
  ];

  declare points: number;
  /** Badge names, in the order they were earned. */
  declare badges: string[];

  constructor() {
    super();
    this.points = 0;
    this.badges = [];
  }

  override render() {
    return html`
      <button popovertarget="badges" title=${msg('Your points and badges')} data-testid="score">
        <span>★ ${this.points === 1 ? msg('1 point') : msg(str`${this.points} points`)}</span>
        <span>◆ ${this.badges.length === 1 ? msg('1 badge') : msg(str`${this.badges.length} badges`)}</span>
      </button>
      <div id="badges" popover>
        <h3>${msg('Your badges')}</h3>
        ${
          this.badges.length === 0
            ? html`<p class="muted">${msg('No badges yet. Finish levels, render an image or play without hints to earn them.')}</p>`
            : html`<ul>
              ${this.badges.map((name) => html`<li>${name}</li>`)}
            </ul>`
        }
      </div>
    `;
  }
}

customElements.define('rt-score', RtScore);

declare global {
  interface HTMLElementTagNameMap {
    'rt-score': RtScore;
  }
}
