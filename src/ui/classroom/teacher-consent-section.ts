import { msg, str } from '@lit/localize';
import { html, nothing } from 'lit';
import type { Assignment } from '../../classroom/assignment.ts';
import { CONSENT_MAX } from '../../classroom/assignment-schema.ts';
import { defaultConsentText } from '../../classroom/consent-text.ts';

/**
 * The teacher page's section for the information pupils read before they give their code
 * and start (consent-text.ts): shown when the assignment asks for participant codes, since
 * only then does the game show it. Left empty, pupils read the app's default text in their
 * language, which the field shows as its placeholder. `change` gets the text, or undefined
 * for the default.
 */
export function consentSection(assignment: Assignment, change: (consent: string | undefined) => void) {
  if (!assignment.askParticipantCode) return nothing;
  const typed = (event: Event) => {
    const text = (event.target as HTMLTextAreaElement).value.trim();
    change(text === '' ? undefined : text);
  };
  return html`<section>
    <h2>${msg('Information before the start')}</h2>
    <!-- The field outside its label: the label's bold would make the grey default text hard to read. -->
    <label class="field" for="consent">
      ${msg('What students read before they type their code: what is recorded, who sees it, that taking part is voluntary, how to withdraw')}
    </label>
    <textarea id="consent" name="consent" rows="8" style="width: 100%" maxlength=${CONSENT_MAX} .value=${assignment.consent ?? ''} placeholder=${defaultConsentText()} @input=${typed}></textarea>
    <p class="muted">
      ${msg(str`Left empty, students read the text shown in grey, in their language. Up to ${CONSENT_MAX} characters; a blank line starts a new paragraph.`)}
    </p>
  </section>`;
}
