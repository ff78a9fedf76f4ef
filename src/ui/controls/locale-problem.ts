import { msg } from '@lit/localize';
import { dutchTextsProblem } from '../../i18n/locale.ts';
import './rt-load-problem.ts';

/**
 * When the Dutch texts could not be loaded (at the start, or when Dutch is chosen in the Menu):
 * a message at the top of the page, in English since Dutch failed, with Reload and Close; the
 * app goes on in English. Shown once; nothing when the Dutch texts loaded or were not asked for.
 */
export function showLocaleProblem(document: Document): void {
  const reason = dutchTextsProblem();
  if (reason === null || document.querySelector('rt-load-problem.locale-problem')) return;
  const problem = document.createElement('rt-load-problem');
  problem.className = 'locale-problem';
  problem.text = msg('The Dutch texts could not be loaded, so the app is in English.');
  problem.reason = reason;
  problem.closable = true;
  document.body.append(problem);
}
