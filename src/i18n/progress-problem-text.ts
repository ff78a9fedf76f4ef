import { msg, str } from '@lit/localize';
import type { ProgressProblem, SaveProblemKind } from '../quest/progress-store.ts';

/**
 * What the learner reads when saved progress cannot be used or saved, in the app's language.
 * The progress store is pure (no lit) and words its problems in English only; it gives their
 * kind, and these are the same sentences through msg().
 */

/** Why the saved progress could not be used, what happens now, and where the old data is. */
export function progressProblemText(problem: ProgressProblem): string {
  if (problem.kind === 'unreadable-storage') {
    return msg('This browser does not let the app read its storage, so progress lasts only while this page is open. Export it to keep it.');
  }
  const what = {
    damaged: () => msg('Your saved progress is damaged and could not be read.'),
    foreign: () => msg('The saved data is not Ray Tracer Quest progress.'),
    'other-version': () => msg('Your saved progress was made by another version of Ray Tracer Quest.'),
  }[problem.kind]();
  const backupKey = problem.backupKey;
  const kept = backupKey ? msg(str`The old data is kept as a backup (${backupKey}).`) : msg('The old data could not be kept in the browser: download it now if you want it.');
  return `${what} ${msg('You start from the beginning.')} ${kept}`;
}

/** Why progress is not being saved, and what the learner can do. */
export function saveProblemText(kind: SaveProblemKind): string {
  return kind === 'storage-full'
    ? msg("The browser's storage is full, so progress is not saved. It is kept while this page is open: export it to keep it.")
    : msg('The browser does not let the app save, so progress is not saved. It is kept while this page is open: export it to keep it.');
}
