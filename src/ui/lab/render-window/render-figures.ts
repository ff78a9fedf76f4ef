/**
 * The figures the render window reports, in words a student can read: how long a render
 * took, how many rays it traced and how many per second.
 */
import { msg, str } from '@lit/localize';
import type { PathCount, RenderProgress } from '../../../render/render-job.ts';
import type { RayStats } from '../../../tracer/ray-tree.ts';
import { localNumbers } from '../../../i18n/number-format.ts';

/** Counts in units ("12,3 thousand" in Dutch) have 3 significant digits, so at most 2 decimals. */
const inUnitsFormat = localNumbers({ maximumFractionDigits: 2 });
const seconds2 = localNumbers({ minimumFractionDigits: 2, maximumFractionDigits: 2 });
const tenths = localNumbers({ minimumFractionDigits: 1, maximumFractionDigits: 1 });
const wholeNumbers = localNumbers({ maximumFractionDigits: 0 });

/** Every ray the render traced: primary, shadow, reflected and refracted. */
export function countRays(stats: RayStats): number {
  return stats.primary + stats.shadow + stats.reflect + stats.refract;
}

/** Rays per second; a render faster than 1 ms counts as 1 ms rather than dividing by zero. */
export function raysPerSecond(rays: number, ms: number): number {
  return rays / (Math.max(ms, 1) / 1000);
}

/** In the reader's language: 950 → "950", 12 345 → "12.3 thousand" ("12,3 duizend"), 4 561 000 → "4.56 million", 2.1e9 → "2.1 billion". */
export function formatCount(count: number): string {
  // Rounded before the unit is chosen, so that 999 960 reads "1 million", not "1000 thousand".
  const rounded = Number(count.toPrecision(3));
  // Re-rounded after dividing: 1.23e6 / 1e6 may come out as 1.2300000000000002.
  const inUnits = (unit: number) => inUnitsFormat.format(Number((rounded / unit).toPrecision(3)));
  if (rounded < 1e3) return String(Math.round(rounded));
  if (rounded < 1e6) return msg(str`${inUnits(1e3)} thousand`);
  if (rounded < 1e9) return msg(str`${inUnits(1e6)} million`);
  return msg(str`${inUnits(1e9)} billion`);
}

/** "850 ms" under a second, "1.23 s" ("1,23 s" in Dutch) under a minute, "2 min 5 s" beyond. */
export function formatDuration(ms: number): string {
  if (ms < 1000) return msg(str`${Math.round(ms)} ms`);
  if (ms < 60_000) return msg(str`${seconds2.format(ms / 1000)} s`);
  const seconds = Math.round(ms / 1000);
  return msg(str`${Math.floor(seconds / 60)} min ${seconds % 60} s`);
}

/** An estimated wait in the largest unit that reads naturally: "40 s", "12 min", "3 h", "27 days". */
export function formatWait(seconds: number): string {
  if (seconds < 90) return msg(str`${Math.max(1, Math.round(seconds))} s`);
  if (seconds < 90 * 60) return msg(str`${Math.round(seconds / 60)} min`);
  if (seconds < 48 * 3600) return msg(str`${Math.round(seconds / 3600)} h`);
  return msg(str`${Math.round(seconds / 86_400)} days`);
}

/** The render's time left, "about 2 min left"; past 20 s in steps of 5 s, so that it does not flicker. */
export function formatTimeLeft(secondsLeft: number): string {
  const seconds = secondsLeft < 20 ? secondsLeft : Math.round(secondsLeft / 5) * 5;
  return msg(str`about ${formatWait(seconds)} left`);
}

/**
 * The pass under way and how far into it: "Step 1 of 4: quick preview 40 %", then "sharp
 * picture (1 sample per pixel)", then "full quality"; "Rendering 42 %" for a render of one
 * pass. Each pass counts from 0 to 100 %, so even a render of days shows movement at once.
 * Path mode's passes that refine the picture say how many paths per pixel it holds: "37 of
 * 256 paths per pixel, 14 %" (the render's share done, as the bar shows it).
 */
export function progressText({
  phase,
  pass,
  passes,
  done,
  total,
  paths,
}: Pick<RenderProgress, 'phase' | 'pass' | 'passes' | 'done' | 'total'> & { paths?: PathCount | null }): string {
  if (paths)
    return msg(
      str`${wholeNumbers.format(paths.done)} of ${wholeNumbers.format(paths.total)} paths per pixel, ${formatPercent(Math.floor(paths.fraction * 1e6), 1e6)}`,
    );
  const percent = formatPercent(done, total);
  if (passes === 1) return msg(str`Rendering ${percent}`);
  switch (phase) {
    case 'preview':
      return msg(str`Step ${pass} of ${passes}: quick preview ${percent}`);
    case 'sharp':
      return msg(str`Step ${pass} of ${passes}: sharp picture (1 sample per pixel) ${percent}`);
    case 'final':
      return msg(str`Step ${pass} of ${passes}: full quality ${percent}`);
  }
}

/**
 * done / total as a percentage, rounded down so that only a finished pass reads 100 %; with
 * one decimal under 10 %, where a long pass would otherwise sit at "0 %" for minutes.
 */
export function formatPercent(done: number, total: number): string {
  // Per mille from the whole numbers, so that 57 of 1000 reads 5.7, not 5.6 (0.057 × 1000 = 56.99…).
  const perMille = Math.min(1000, Math.max(0, Math.floor((1000 * done) / Math.max(total, 1))));
  if (perMille < 100) return `${tenths.format(perMille / 10)} %`;
  return `${Math.floor(perMille / 10)} %`;
}

/** How full the progress bar is, 0..1: the pass's share of its rays, or in path mode's refining passes the render's. */
export function progressFraction({ done, total, paths }: Pick<RenderProgress, 'done' | 'total'> & { paths?: PathCount | null }): number {
  return paths ? paths.fraction : done / Math.max(total, Number.MIN_VALUE);
}

/** A cancelled path render's picture: "Each of its pixels holds at least 37 of the 256 paths." */
export function pathsOnShow({ done, total }: PathCount): string {
  return msg(str`Each of its pixels holds at least ${wholeNumbers.format(done)} of the ${wholeNumbers.format(total)} paths.`);
}
