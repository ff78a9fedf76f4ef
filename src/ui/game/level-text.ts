import { html, type TemplateResult } from 'lit';
import { localize, type Locale, type LocalizedText } from '../../quest/localized-text.ts';
import { markupParts } from '../../quest/text-markup.ts';

/**
 * A level's text as the task column shows it: in the learner's language, with each on-screen
 * name (`**Render image**`, src/quest/text-markup.ts) in bold. Every piece goes into the
 * template as a value, never as HTML, so lit escapes whatever a level file holds.
 */
export function levelText(text: LocalizedText, locale: Locale): TemplateResult {
  return html`${markupParts(localize(text, locale)).map((part) => (part.marked ? html`<strong>${part.text}</strong>` : part.text))}`;
}
