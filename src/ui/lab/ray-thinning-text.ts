import { msg, str } from '@lit/localize';
import { localNumbers } from '../../i18n/number-format.ts';
import type { Thinning } from '../../view/ray-budget.ts';

const counts = localNumbers();

/**
 * What the 3D view says while it draws only some of the rays (it changes with every step: not
 * announced). A heavy screen traced from one sample per pixel has no count of its own: the
 * one told is the last screen's traced whole, before the edit. Only the view's code asks for
 * it, so it loads with that code (rt-scene-view.ts), not before the first screen.
 */
export function thinningText({ shown, of, oneSample }: Thinning): string {
  if (!oneSample && of !== null) return msg(str`Showing ${counts.format(shown)} of ${counts.format(of)} rays while you edit.`);
  if (of === null)
    return msg(str`Showing ${counts.format(shown)} rays while you edit, each pixel traced from one of its samples. All come back when you stop.`);
  return msg(
    str`Showing ${counts.format(shown)} rays while you edit, each pixel traced from one of its samples (${counts.format(of)} rays before the edit). All come back when you stop.`,
  );
}
