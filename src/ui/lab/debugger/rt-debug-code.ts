import { msg } from '@lit/localize';
import { css, html, type PropertyValues } from 'lit';
import { LocalizedElement } from '../../controls/localized-element.ts';
import { styleMap } from 'lit/directives/style-map.js';
import { LINE_INDENT, PSEUDOCODE_LINES, type PseudocodeLine } from '../../../debugger/pseudocode.ts';
import { pseudocodeText } from './debugger-text.ts';
import { revealRow } from './reveal-row.ts';
import { scrollCue } from './scroll-cue.ts';

/**
 * @summary The ray tracer as 14 lines of pseudocode, with the line the debugger is on lit:
 * a marker (▶) and a tinted band, and `aria-current="step"` for screen readers, so colour is
 * not the only sign.
 *
 * `line`: the current line's id (pseudocode.ts), or null before the first step.
 * @csspart line - each line of code
 */
export class RtDebugCode extends LocalizedElement {
  static override properties = { line: {} };

  static override styles = css`
    /* The host is what scrolls (the debugger makes it so): the border and the scroll cue are on it. */
    :host {
      display: block;
      box-sizing: border-box;
      border-radius: 6px;
      border: 1px solid var(--rt-border);
      --cue-bg: var(--rt-bg);
      ${scrollCue}
    }
    ol {
      margin: 0;
      padding: 6px 0;
      list-style: none;
      font-family: ui-monospace, 'SFMono-Regular', Menlo, Consolas, monospace;
      font-size: 0.74rem;
      line-height: 1.35;
      counter-reset: line;
    }
    /* Narrow gutters (number, marker, indent): the dock's column is about 190 px at 1366×768. */
    li {
      display: flex;
      gap: 3px;
      padding: 0 6px 0 0;
      counter-increment: line;
      color: var(--rt-muted);
    }
    li::before {
      content: counter(line);
      flex: 0 0 1.7em;
      text-align: right;
      opacity: 0.7;
    }
    .marker {
      flex: 0 0 0.9em;
    }
    li[aria-current='step'] {
      background: var(--rt-accent-soft);
      color: var(--rt-text);
      font-weight: 600;
    }
    /* Lines wrap between words; a word is split only when it is wider than the whole column. */
    .code {
      min-width: 0;
      white-space: pre-wrap;
      overflow-wrap: break-word;
    }
  `;

  declare line: PseudocodeLine | null;

  constructor() {
    super();
    this.line = null;
  }

  protected override updated(changed: PropertyValues<this>): void {
    // The lit line stays in view when the list scrolls (a short dock).
    if (changed.has('line')) revealRow(this, this.renderRoot.querySelector('[aria-current="step"]'));
  }

  override render() {
    return html`<ol aria-label=${msg('The ray tracer, in pseudocode')}>
      ${PSEUDOCODE_LINES.map((line) => {
        const current = line === this.line;
        return html`<li part="line" data-line=${line} aria-current=${current ? 'step' : 'false'}>
          <span class="marker" aria-hidden="true">${current ? '▶' : ''}</span>
          <span class="code" style=${styleMap({ paddingLeft: `${LINE_INDENT[line]}em` })}>${pseudocodeText(line)}</span>
        </li>`;
      })}
    </ol>`;
  }
}

customElements.define('rt-debug-code', RtDebugCode);

declare global {
  interface HTMLElementTagNameMap {
    'rt-debug-code': RtDebugCode;
  }
}
