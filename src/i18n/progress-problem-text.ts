import { msg, str } from '@lit/localize';
import type { ProgressProblem, SaveProblemKind } from '../quest/progress-store.ts';
import { answersCounted, pointsCounted } from './counted.ts';
import { shortList } from './short-list.ts';

/**
 * What the learner reads when saved progress cannot be used as it was, or cannot be saved,
 * in the app's language. The stores are pure (no lit) and give kinds; these are the
 * sentences, each saying what happened and what the learner can do. A save is never said to
 * have happened unless it did.
 */

/** Why the saved progress could not be used as it was, what was kept, and where the old data is. */
export function progressProblemText(problem: ProgressProblem, points: number): string {
  if (problem.kind === 'unreadable-storage') {
    return msg('This browser does not let the app read its storage, so progress lasts only while this page is open. Export it to keep it.');
  }
  const kept = problem.backupKey
    ? msg('The saved data as it was is kept: download or restore it from the Menu (Damaged saves).')
    : msg('There is no room to keep a copy of the saved data as it was, so nothing is saved over it until you download it from the Menu (Damaged saves).');
  if (problem.kind === 'repaired') {
    const count = problem.reasons.length;
    const left = shortList(placesOf(problem.reasons), 3, ', ');
    return `${msg(str`Part of your saved progress was damaged, and what was damaged is left out (${count}: ${left}); the rest is kept: ${pointsCounted(points)}.`)} ${kept}`;
  }
  const what = {
    damaged: () => msg('Your saved progress is damaged and could not be read.'),
    foreign: () => msg('The saved data is not Ray Tracer Quest progress.'),
    'other-version': () => msg('Your saved progress was made by another version of Ray Tracer Quest.'),
  }[problem.kind]();
  return `${what} ${msg('You start from the beginning.')} ${kept}`;
}

/** Why progress is not being saved, and what the learner can do. */
export function saveProblemText(kind: SaveProblemKind): string {
  switch (kind) {
    case 'storage-full':
      return msg(
        "The browser's storage is full, so progress is not saved. It is kept while this page is open and saved as soon as there is room: export it (Menu) to be safe.",
      );
    case 'storage-blocked':
      return msg('The browser does not let the app save, so progress is not saved. It is kept while this page is open: export it to keep it.');
    case 'damaged-held':
      return msg(
        "A damaged save could not be copied (the browser's storage is full), so nothing is saved over it. Download it from the Menu (Damaged saves) and saving goes on; until then what is not saved is kept while this page is open.",
      );
  }
}

/** The reason in a few words, inside another sentence ("… could not be saved: <reason>."). */
export function saveProblemReason(kind: SaveProblemKind): string {
  switch (kind) {
    case 'storage-full':
      return msg("the browser's storage has no room for it");
    case 'storage-blocked':
      return msg('the browser does not let the app save');
    case 'damaged-held':
      return msg('a damaged save must be downloaded from the Menu (Damaged saves) first');
  }
}

/** A damaged session record (participant code and attempt): what could not be read, and where the record is. */
export function contextDamageText(damage: { codeLost: boolean; attemptLost: boolean; backedUp: boolean }): string {
  const lost = [
    damage.codeLost ? msg('Your saved participant code could not be read: please type it again.') : '',
    damage.attemptLost ? msg('The record of your attempt could not be read, so your downloads will count this as a new attempt.') : '',
  ].filter((text) => text !== '');
  const what = lost.length > 0 ? lost.join(' ') : msg('The record of your participant code and attempt was damaged, but both could be read from it.');
  const kept = damage.backedUp
    ? msg('The damaged record is kept: download or restore it from the Menu (Damaged saves).')
    : msg('There is no room to keep a copy of the damaged record, so it is not written over until you download it from the Menu (Damaged saves).');
  return `${what} ${kept}`;
}

/**
 * Damaged survey answers: whether the survey asks again, or how many answers were kept (and
 * left out, when that can be told), and where the record is.
 */
export function surveyDamageText(damage: { askedAgain: boolean; kept: number; leftOut: number | null; backedUp: boolean }): string {
  const { kept, leftOut } = damage;
  const what = damage.askedAgain
    ? msg('Your saved survey answers could not be read, so the survey will ask for them again.')
    : leftOut === null
      ? msg(str`Your saved survey answers were damaged; what could be read of them is kept (${answersCounted(kept)}).`)
      : msg(str`Your saved survey answers were damaged: ${kept} kept, ${leftOut} left out because they could not be read.`);
  const where = damage.backedUp
    ? msg('The damaged answers are kept: download or restore them from the Menu (Damaged saves).')
    : msg('There is no room to keep a copy of the damaged answers, so they are not written over until you download them from the Menu (Damaged saves).');
  return `${what} ${where}`;
}

/**
 * The places of `path: reason (what was done)` lines ("settings.locale", "log.events[12]"):
 * short enough for a message; the reasons are in the download for whoever wants them.
 */
export function placesOf(notes: readonly string[]): string[] {
  return notes.map((note) => note.slice(0, note.indexOf(': ') < 0 ? undefined : note.indexOf(': ')));
}
