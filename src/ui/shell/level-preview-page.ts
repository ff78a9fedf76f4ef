import { msg } from '@lit/localize';
import { html } from 'lit';
import { loadBrowserCatalog } from '../../app/level-catalog-browser.ts';
import { previewAssignment } from '../../classroom/level-preview.ts';
import { currentLocale } from '../../i18n/locale.ts';
import { playableLevels } from '../../quest/level-index.ts';
import './rt-link-notice.ts';
import './rt-preview-notice.ts';

/**
 * `#/preview/<level id>`: the level in the lab, in preview (the lab's `preview` attribute:
 * nothing saved, see classroom/level-preview.ts), with a note that says so. A level this
 * game does not have says that instead of opening something else.
 */
export function levelPreviewPage(levelId: string) {
  const level = playableLevels(loadBrowserCatalog()).find((candidate) => candidate.id === levelId);
  if (!level)
    return html`<rt-link-notice .text=${msg('This preview names a level this version of the game does not have.')}></rt-link-notice><rt-lab></rt-lab>`;
  return html`<rt-preview-notice></rt-preview-notice><rt-lab preview .assignment=${previewAssignment(level, currentLocale())}></rt-lab>`;
}
