import { msg, str } from '@lit/localize';
import { LAB_CODE_MAX, type CodeNotImported } from '../quest/progress-lab-code.ts';
import { localNumbers } from './number-format.ts';
import { shortList } from './short-list.ts';

const WHOLE = localNumbers({ maximumFractionDigits: 0 });

/**
 * What became of an imported file's code of the code labs, as sentences to add to the import
 * message; '' when all of it was imported. Each says that the code already in this browser
 * for those labs is kept, which is true (quest-session.ts importText).
 */
export function labCodeImportText(code: CodeNotImported | undefined): string {
  if (!code) return '';
  const labs = (names: readonly string[]) =>
    names.includes('')
      ? msg('every lab')
      : shortList(
          names.map((name) => `“${name}”`),
          3,
          ', ',
        );
  const most = WHOLE.format(LAB_CODE_MAX);
  const refused =
    code.refused.length > 0
      ? ` ${msg(str`Your code for ${labs(code.refused)} was not imported: a lab's code in a progress file must be text of at most ${most} characters. The code this browser had for it is kept.`)}`
      : '';
  const notSaved =
    code.notSaved.length > 0
      ? ` ${msg(str`Your code for ${labs(code.notSaved)} could not be saved in this browser (storage full or blocked): the code it had for it is kept.`)}`
      : '';
  return refused + notSaved;
}
