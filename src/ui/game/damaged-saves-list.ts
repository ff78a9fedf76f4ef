import { msg, str } from '@lit/localize';
import { css, html, nothing, type TemplateResult } from 'lit';
import type { DamagedSave } from '../../app/damaged-saves.ts';
import { currentLocale } from '../../i18n/locale.ts';
import { localNumbers } from '../../i18n/number-format.ts';
import type { ProgressCommand } from './rt-progress-menu.ts';

const KILOBYTES = localNumbers({ maximumFractionDigits: 0 });

/**
 * The Menu's "Damaged saves": each copy of saved data that could not be used as it was
 * (src/app/damaged-saves.ts), with Download (the exact text), Restore (what can be read of
 * it joins the progress) and Delete (once downloaded, to free space). A save still held
 * under its own key (no room for a copy) can only be downloaded: that lets saving go on.
 */
export function damagedSavesList(saves: readonly DamagedSave[], send: (command: ProgressCommand) => void): TemplateResult | typeof nothing {
  if (saves.length === 0) return nothing;
  return html`<fieldset class="damaged">
    <legend>${msg('Damaged saves')}</legend>
    <ul>
      ${saves.map(
        (save) => html`<li data-damaged-save=${save.key}>
          <span>${describe(save)}</span>
          <span class="row">
            <button @click=${() => send({ kind: 'damaged-download', key: save.key })} title=${msg('Download this save exactly as it was')}>${msg('Download')}</button>
            ${
              save.held
                ? nothing
                : html`<button @click=${() => send({ kind: 'damaged-restore', key: save.key })} title=${msg('Take back into your progress what can be read of this save')}>${msg('Restore')}</button>
                  <button class="danger" @click=${() => send({ kind: 'damaged-delete', key: save.key })} title=${msg('Delete this copy from the browser, to free space (download it first)')}>${msg('Delete')}</button>`
            }
          </span>
        </li>`,
      )}
    </ul>
  </fieldset>`;
}

function describe(save: DamagedSave): string {
  const what = {
    progress: () => msg('Progress'),
    session: () => msg('Participant code and attempt'),
    survey: () => msg('Survey answers'),
    'concept-test': () => msg('Concept test answers'),
  }[save.what]();
  const size = KILOBYTES.format(Math.max(1, save.size / 1000));
  if (!save.madeAt) return msg(str`${what}, not copied (no room), ${size} kB: download it so that saving can go on`);
  const when = new Date(save.madeAt).toLocaleString(currentLocale(), { dateStyle: 'medium', timeStyle: 'short' });
  return msg(str`${what}, kept on ${when}, ${size} kB`);
}

export const damagedSavesStyles = css`
  .damaged ul {
    margin: 0;
    padding: 0;
    list-style: none;
    display: grid;
    gap: 8px;
  }
  .damaged li {
    display: grid;
    gap: 4px;
    font-size: 0.875rem;
  }
  .damaged .row {
    display: flex;
    gap: 6px;
    flex-wrap: wrap;
  }
  .damaged .row button {
    flex: 1 1 auto;
  }
  .save-problem {
    color: var(--rt-danger);
    font-size: 0.875rem;
  }
`;
