import { msg } from '@lit/localize';
import { html, type TemplateResult } from 'lit';
import { until } from 'lit/directives/until.js';
import { laterLevelText, laterLevelTextNow } from '../../app/later-level-texts.ts';
import { localize, type LocalizedText, type Locale } from '../../quest/localized-text.ts';
import { levelText } from './level-text.ts';

/**
 * An "Explain more" toggle; `opened` hears when the learner opens it (the engine logs it). Its
 * words may load later than the level (scripts/level-texts-plugin.ts): then they are fetched
 * as it renders, and "Loading…" stands in for the moment that takes.
 */
export function explainMore(text: LocalizedText, locale: Locale, opened: () => void): TemplateResult {
  const words = localize(text, locale);
  const now = laterLevelTextNow(words);
  const shown =
    now !== null
      ? levelText(now, locale)
      : until(
          laterLevelText(words).then((found) => levelText(found, locale)),
          msg('Loading…'),
        );
  return html`<details class="more" @toggle=${(event: Event) => (event.target as HTMLDetailsElement).open && opened()}>
    <summary>${msg('Explain more')}</summary>
    <p>${shown}</p>
  </details>`;
}
