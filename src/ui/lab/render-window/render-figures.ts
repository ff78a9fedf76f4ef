/**
 * The figures the render window reports, in words a student can read: how long a render
 * took, how many rays it traced and how many per second.
 */
import { msg, str } from '@lit/localize';
import type { RenderProgress } from '../../../render/render-job.ts';
import type { RayStats } from '../../../tracer/ray-tree.ts';
import { localNumbers } from '../../../i18n/number-format.ts';

/** Counts in units ("12,3 thousand" in Dutch) have 3 significant digits, so at most 2 decimals. */
const inUnitsFormat = localNumbers({ maximumFractionDigits: 2 });
const seconds2 = localNumbers({ minimumFractionDigits: 2, maximumFractionDigits: 2 });

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

/** "Quick preview…" during the coarse passes, then "Rendering 42 %". */
/** An estimated wait in the largest unit that reads naturally: "40 s", "12 min", "3 h", "27 days". */
export function formatWait(seconds: number): string {
  if (seconds < 90) return msg(str`${Math.max(1, Math.round(seconds))} s`);
  if (seconds < 90 * 60) return msg(str`${Math.round(seconds / 60)} min`);
  if (seconds < 48 * 3600) return msg(str`${Math.round(seconds / 3600)} h`);
  return msg(str`${Math.round(seconds / 86_400)} days`);
}

export function progressText({ phase, done, total }: RenderProgress): string {
  if (phase === 'preview') return msg('Quick preview…');
  const percent = Math.floor((100 * done) / Math.max(total, 1));
  return msg(str`Rendering ${percent} %`);
}

