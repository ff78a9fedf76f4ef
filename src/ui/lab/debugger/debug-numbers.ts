import { localNumbers, numberList } from '../../../i18n/number-format.ts';
import type { Color } from '../../../scene/scene.ts';

const number = localNumbers({ minimumFractionDigits: 3, maximumFractionDigits: 3 });

/** "(0.125, 0.500, 1.000)" in the reader's number format (Dutch writes "(0,125; 0,500; 1,000)"). */
export function colorText(color: Color): string {
  return `(${numberList(color.map((value) => number.format(value)))})`;
}
