import { msg, str } from '@lit/localize';
import type { ReactiveController, ReactiveControllerHost } from 'lit';
import type { Assignment } from '../../classroom/assignment.ts';
import type { ClassLearner } from '../../classroom/dashboard-learners.ts';
import { summarizeLevels } from '../../classroom/dashboard-summary.ts';
import { estimatedMinutes } from '../../classroom/level-summary.ts';
import {
  keepMeasuredMinutes,
  measuredMinutes,
  MEASURED_MINUTES_KEY,
  readMeasuredMinutes,
  type MeasuredLevel,
  type MeasuredMinutes,
} from '../../classroom/measured-minutes.ts';
import { formatLocale } from '../../i18n/format-locale.ts';
import type { Level } from '../../quest/level-schema.ts';
import { refusingStorage, type KeyValueStorage } from '../../quest/saved-backups.ts';

/**
 * Minutes per level on the teacher page: the median active time a class took
 * (classroom/measured-minutes.ts) when the dashboard in this browser has seen results for
 * the level, else the stated estimate from its tasks (classroom/level-summary.ts), and the
 * words that say which of the two a figure is.
 */

function browserStorage(): KeyValueStorage {
  try {
    return localStorage;
  } catch {
    return refusingStorage();
  }
}

/** The dashboard keeps the medians of the results it has loaded, for the teacher page. */
export function keepClassMinutes(learners: readonly ClassLearner[]): void {
  keepMeasuredMinutes(browserStorage(), measuredMinutes(summarizeLevels(learners)));
}

/**
 * The medians the dashboard kept, for the teacher page; read again when the dashboard, open
 * in another tab, keeps new ones (the browser's `storage` event), so the page need not be reloaded.
 */
export class MeasuredMinutesController implements ReactiveController {
  levels: MeasuredMinutes = {};

  constructor(
    private readonly host: ReactiveControllerHost,
    private readonly storage: KeyValueStorage = browserStorage(),
  ) {
    host.addController(this);
    this.levels = readMeasuredMinutes(storage);
  }

  private readonly onStorage = (event: StorageEvent): void => {
    if (event.key !== MEASURED_MINUTES_KEY && event.key !== null) return;
    this.levels = readMeasuredMinutes(this.storage);
    this.host.requestUpdate();
  };

  hostConnected(): void {
    addEventListener('storage', this.onStorage);
  }

  hostDisconnected(): void {
    removeEventListener('storage', this.onStorage);
  }
}

/** A level's typical minutes: the class's median rounded to a half minute (at least one half), else the estimate. */
export function levelMinutes(level: Level, required: readonly string[], measured: MeasuredLevel | undefined): number {
  return measured ? Math.max(0.5, Math.round(measured.minutes * 2) / 2) : estimatedMinutes(level, required);
}

/** Minutes in the page's language: "9.5" in English, "9,5" in Dutch. */
export function minutesText(minutes: number): string {
  return new Intl.NumberFormat(formatLocale(), { maximumFractionDigits: 1 }).format(minutes);
}

/** "about 6 min (median of 12 pupils)" or "about 9.5 min (estimate)". */
export function levelMinutesText(level: Level, required: readonly string[], measured: MeasuredLevel | undefined): string {
  const minutes = minutesText(levelMinutes(level, required, measured));
  if (!measured) return msg(str`about ${minutes} min (estimate)`);
  return measured.learners === 1
    ? msg(str`about ${minutes} min (time of 1 student)`)
    : msg(str`about ${minutes} min (median of ${measured.learners} students)`);
}

/** The whole assignment's minutes, and where they come from, under the level list. */
export function totalMinutesText(a: Assignment, levels: readonly Level[], measured: MeasuredMinutes): string {
  let total = 0;
  let anyMeasured = false;
  for (const id of a.levels) {
    const level = levels.find((candidate) => candidate.id === id);
    if (!level) continue;
    total += levelMinutes(level, a.requiredTasks[id] ?? [], measured[id]);
    anyMeasured ||= measured[id] !== undefined;
  }
  const minutes = minutesText(total);
  return anyMeasured
    ? msg(
        str`In all about ${minutes} minutes: the median active time of students whose results the dashboard in this browser has read, and an estimate from the kinds of task for levels it has no results of.`,
      )
    : msg(str`In all about ${minutes} minutes for the required tasks (an estimate from the kinds of task, not measured).`);
}
