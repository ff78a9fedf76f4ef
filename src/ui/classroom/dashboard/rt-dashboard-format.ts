import { msg, str } from '@lit/localize';

/** Shared wording of the dashboard's charts and tables. */

/** A time as a teacher reads it: "45 s", "2 min", "3 min 05 s", "1 h 02 min". */
export function formatDuration(ms: number): string {
  const seconds = Math.round(ms / 1000);
  if (seconds < 60) return msg(str`${seconds} s`);
  const minutes = Math.floor(seconds / 60);
  if (minutes < 60) return seconds % 60 === 0 ? msg(str`${minutes} min`) : msg(str`${minutes} min ${String(seconds % 60).padStart(2, '0')} s`);
  return msg(str`${Math.floor(minutes / 60)} h ${String(minutes % 60).padStart(2, '0')} min`);
}

/** A share as a whole percentage: "67 %". */
export function formatPercent(share: number): string {
  return `${Math.round(share * 100)} %`;
}
