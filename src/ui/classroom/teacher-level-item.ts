import { msg, str } from '@lit/localize';
import { html, nothing } from 'lit';
import { levelPreviewHash } from '../../classroom/level-preview.ts';
import { taskKindCounts, type TeacherTaskKind } from '../../classroom/level-summary.ts';
import type { MeasuredLevel } from '../../classroom/measured-minutes.ts';
import { levelMinutesText } from './teacher-minutes.ts';
import type { Level } from '../../quest/level-schema.ts';
import type { Locale } from '../../quest/localized-text.ts';
import { plainLevelText } from '../../quest/text-markup.ts';

/** What the teacher page does for one level of the list. */
export interface LevelItemActions {
  move(index: number, by: -1 | 1): void;
  remove(id: string): void;
  toggleTask(levelId: string, taskId: string, required: boolean): void;
}

export interface LevelItem {
  id: string;
  level: Level | undefined;
  index: number;
  last: number;
  /** The assignment's language: the level's texts are shown as its students read them. */
  locale: Locale;
  idea: string | null;
  required: readonly string[];
  /** The class's median time in the level, when the dashboard in this browser has read results of it. */
  measured?: MeasuredLevel;
}

/**
 * One level of the teacher page's list: its title and one idea, what its required tasks ask
 * (task kinds) and take (a class's median minutes when known, else a stated estimate: teacher-minutes.ts), a
 * preview that opens it without the levels before it, the buttons that order or remove it,
 * and its tasks to require.
 */
export function levelItem(item: LevelItem, actions: LevelItemActions) {
  const { id, level, index, last, locale, idea, required, measured } = item;
  const title = level ? plainLevelText(level.title, locale) : id;
  return html`<li data-level=${id}>
    <div class="level-head">
      <span class="level-name"><strong>${title}</strong>${idea === null ? nothing : html`<span class="idea">${idea}</span>`}</span>
      <a class="button" href=${levelPreviewHash(id)} target="_blank" rel="noopener" title=${msg('Play this level in a new tab without the ones before it; nothing is saved')}
        >${msg('Preview')}</a
      >
      <button class="icon" type="button" data-move="-1" ?disabled=${index === 0} aria-label=${msg(str`Move ${title} up`)} title=${msg('Move up')} @click=${() => actions.move(index, -1)}>↑</button>
      <button class="icon" type="button" data-move="1" ?disabled=${index === last} aria-label=${msg(str`Move ${title} down`)} title=${msg('Move down')} @click=${() => actions.move(index, 1)}>↓</button>
      <button class="icon" type="button" aria-label=${msg(str`Remove ${title}`)} title=${msg('Remove from the assignment')} @click=${() => actions.remove(id)}>✕</button>
    </div>
    ${level ? html`<p class="level-facts">${levelFacts(level, required, measured)}</p>` : nothing}
    ${
      level
        ? html`<fieldset>
          <legend>${msg('Required tasks (the others are optional)')}</legend>
          ${level.tasks.map(
            (task) => html`<label class="check">
              <input type="checkbox" name=${`${id}/${task.id}`} .checked=${required.includes(task.id)} @change=${(e: Event) => actions.toggleTask(id, task.id, (e.target as HTMLInputElement).checked)} />
              ${plainLevelText(task.title, locale)} ${task.mandatory ? nothing : html`<span class="muted">${msg('(optional in the level)')}</span>`}
            </label>`,
          )}
        </fieldset>`
        : nothing
    }
  </li>`;
}

/** "Required: 6 in the lab, 2 questions · about 9,5 min (estimate)" (the page's language, its decimal mark). */
export function levelFacts(level: Level, required: readonly string[], measured?: MeasuredLevel): string {
  const kinds = taskKindCounts(level, required).map(({ kind, count }) => kindText(kind, count));
  const time = levelMinutesText(level, required, measured);
  return kinds.length === 0 ? msg(str`No required tasks · ${time}`) : msg(str`Required: ${kinds.join(', ')} · ${time}`);
}

function kindText(kind: TeacherTaskKind, count: number): string {
  switch (kind) {
    case 'action':
      return count === 1 ? msg('1 thing to do in the lab') : msg(str`${count} things to do in the lab`);
    case 'challenge':
      return count === 1 ? msg('1 target picture to match') : msg(str`${count} target pictures to match`);
    case 'code':
      return count === 1 ? msg('1 function to write') : msg(str`${count} functions to write`);
    case 'question':
      return count === 1 ? msg('1 question') : msg(str`${count} questions`);
    case 'picture':
      return count === 1 ? msg('1 picture to choose') : msg(str`${count} pictures to choose`);
    case 'estimate':
      return count === 1 ? msg('1 number to estimate') : msg(str`${count} numbers to estimate`);
    case 'read':
      return count === 1 ? msg('1 text to read') : msg(str`${count} texts to read`);
  }
}
