import { msg, str } from '@lit/localize';
import { css, html } from 'lit';
import { LocalizedElement } from '../controls/localized-element.ts';
import { fire, gameStyles } from './game-styles.ts';

/**
 * @summary The end of an assignment, when a learner comes back to it after passing every
 * level (and handing in the survey, if it has one): what is left is handing in the data.
 *
 * @fires open-map - CustomEvent<null>: the learner wants the level map (to replay a level).
 */
export class RtAssignmentDone extends LocalizedElement {
  static override properties = { heading: {} };
  static override styles = [
    gameStyles,
    css`
      :host {
        display: block;
      }
    `,
  ];

  /** The assignment's title. */
  declare heading: string;

  constructor() {
    super();
    this.heading = '';
  }

  override render() {
    return html`<section role="status">
      <h2>${msg('Assignment finished')}</h2>
      <p>${msg(str`You have finished every level of "${this.heading}". Well done!`)}</p>
      <p>${msg('Download your data below and hand it in to your teacher.')}</p>
      <button @click=${() => fire(this, 'open-map', null)}>${msg('Level map')}</button>
    </section>`;
  }
}

customElements.define('rt-assignment-done', RtAssignmentDone);

declare global {
  interface HTMLElementTagNameMap {
    'rt-assignment-done': RtAssignmentDone;
  }
}
