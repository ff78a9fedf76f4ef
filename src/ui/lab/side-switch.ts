import { msg } from '@lit/localize';
import { html, type TemplateResult } from 'lit';

/**
 * The two buttons over the lab's column on a small screen (lab-compact.css.ts): that column
 * shows the level's tasks or the panels, not both, so that the 3D view keeps its room. The
 * buttons are named as the two areas are. Hidden on wide screens, where both are shown.
 */
export function sideSwitch(panelsShown: boolean, show: (panels: boolean) => void): TemplateResult {
  return html`<div class="side-switch" role="group" aria-label=${msg('Show in the column')}>
    <button data-command="show-tasks" aria-pressed=${panelsShown ? 'false' : 'true'} @click=${() => show(false)}>${msg('Tasks')}</button>
    <button data-command="show-panels" aria-pressed=${panelsShown ? 'true' : 'false'} @click=${() => show(true)}>${msg('Scene and settings')}</button>
  </div>`;
}
