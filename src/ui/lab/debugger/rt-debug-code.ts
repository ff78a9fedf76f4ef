import { msg } from '@lit/localize';
import { css, html, LitElement, type PropertyValues } from 'lit';
import { styleMap } from 'lit/directives/style-map.js';
import { LINE_INDENT, PSEUDOCODE_LINES, type PseudocodeLine } from '../../../debugger/pseudocode.ts';
import { pseudocodeText } from './debugger-text.ts';

/**
 * @summary The ray tracer as 14 lines of pseudocode, with the line the debugger is on lit:
 * a marker (▶) and a tinted band, and `aria-current="step"` for screen readers, so colour is
 * not the only sign.
 *
 * `line`: the current line's id (pseudocode.ts), or null before the first step.
 * @csspart line - each line of code
 */
export class RtDebugCode extends LitElement {
  static override properties = { line: {} };

  static override styles = css`
    :host {
      display: block;
    }
    ol {
      margin: 0;
      padding: 6px 0;
      list-style: none;
      font-family: ui-monospace, 'SFMono-Regular', Menlo, Consolas, monospace;
      font-size: 0.74rem;
      line-height: 1.35;
      border-radius: 6px;
      background: var(--rt-bg);
      border: 1px solid var(--rt-border);
      counter-reset: line;
    }
    li {
      display: flex;
      gap: 6px;
      padding: 0 8px 0 0;
      counter-increment: line;
      color: var(--rt-muted);
    }
    li::before {
      content: counter(line);
      flex: 0 0 2.2em;
      text-align: right;
      opacity: 0.7;
    }
    .marker {
      flex: 0 0 1em;
    }
    li[aria-current='step'] {
      background: var(--rt-accent-soft);
      color: var(--rt-text);
      font-weight: 600;
    }
    .code {
      white-space: pre-wrap;
      overflow-wrap: anywhere;
    }
  `;

  declare line: PseudocodeLine | null;

  constructor() {
    super();
    this.line = null;
  }

  protected override updated(changed: PropertyValues<this>): void {
    // The lit line stays in view when the list scrolls (a short dock).
    if (changed.has('line')) this.renderRoot.querySelector('[aria-current="step"]')?.scrollIntoView({ block: 'nearest' });
  }

  override render() {
    return html`<ol aria-label=${msg('The ray tracer, in pseudocode')}>
      ${PSEUDOCODE_LINES.map((line) => {
        const current = line === this.line;
        return html`<li part="line" data-line=${line} aria-current=${current ? 'step' : 'false'}>
          <span class="marker" aria-hidden="true">${current ? '▶' : ''}</span>
          <span class="code" style=${styleMap({ paddingLeft: `${LINE_INDENT[line] * 1.2}em` })}>${pseudocodeText(line)}</span>
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
