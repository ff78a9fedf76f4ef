import type { Scene } from '../scene/scene.ts';
import { sameBadge, type Badge, type EarnedBadge } from './badges.ts';
import { EventLog, type LoggedEvent, type QuestClock, type QuestEvent } from './event-log.ts';
import type { Level } from './level-schema.ts';
import { PROGRESS_KIND, PROGRESS_VERSION, type LevelProgress, type Progress, type QuestSettings } from './progress.ts';
import { holdsAll, mergeProgress } from './progress-merge.ts';
import { reconcileLevels } from './progress-reconcile.ts';

/** Called after every change, with the events it logged (none when only the scene or settings changed). */
export type QuestListener = (events: readonly LoggedEvent[]) => void;

/**
 * What the quest engine keeps (quest-engine.ts), saved together as one Progress: each level's
 * record, the badges, the settings, the sandbox, the level to resume and the event log; and
 * who hears of each change. The rules that decide the changes are the engine's.
 */
export class KeptProgress {
  levels: Record<string, LevelProgress>;
  badges: EarnedBadge[];
  settings: QuestSettings;
  sandbox: Scene | null;
  resumable: Progress['current'];
  readonly log: EventLog;
  /** Something was saved that logged no event (the scene, the settings): listeners hear of it all the same. */
  changed = false;
  private readonly epoch: string | undefined;
  private readonly listeners = new Set<QuestListener>();
  private unpublished: LoggedEvent[] = [];

  /** `playable`: the levels that loaded, whose records are reconciled with their files (progress-reconcile.ts). */
  constructor(
    progress: Progress,
    private readonly playable: Level[],
    clock: QuestClock,
    session?: string,
  ) {
    this.levels = reconcileLevels(progress.levels, playable);
    this.badges = progress.badges;
    this.settings = progress.settings;
    this.sandbox = progress.sandbox;
    this.resumable = progress.current;
    this.epoch = progress.epoch;
    this.log = new EventLog(progress.log, clock, session);
  }

  /** Everything to save; the event log inside is shared and only ever grows. */
  get progress(): Progress {
    return {
      kind: PROGRESS_KIND,
      version: PROGRESS_VERSION,
      levels: this.levels,
      badges: this.badges,
      settings: this.settings,
      sandbox: this.sandbox,
      current: this.resumable,
      log: this.log.data,
      ...(this.epoch === undefined ? {} : { epoch: this.epoch }),
    };
  }

  /** A level's record, empty before anything was done in it. */
  levelOf(levelId: string): LevelProgress {
    return this.levels[levelId] ?? { tasks: {}, hintsUsed: 0 };
  }

  append(event: QuestEvent): LoggedEvent {
    const logged = this.log.append(event);
    this.unpublished.push(logged);
    return logged;
  }

  /** Earns a badge once: a badge already earned is not logged again. */
  award(badge: Badge): void {
    if (this.badges.some((earned) => sameBadge(earned.badge, badge))) return;
    const logged = this.append({ type: 'badge.earned', badge });
    this.badges = [...this.badges, { badge, t: logged.t }];
  }

  subscribe(listener: QuestListener): () => void {
    this.listeners.add(listener);
    return () => this.listeners.delete(listener);
  }

  /** Tells listeners once per call from outside, with everything that call logged. */
  publish(): void {
    if (this.unpublished.length === 0 && !this.changed) return;
    const events = this.unpublished;
    this.unpublished = [];
    this.changed = false;
    for (const listener of [...this.listeners]) listener(events);
  }

  /**
   * Takes in what another tab saved (progress-merge.ts): its events, tasks, badges and hint
   * counts join ours, and its settings replace ours (the learner changed them there last).
   * False when there was nothing new, or when it is of another epoch (a reset or import there).
   */
  absorb(theirs: Progress): boolean {
    const ours = this.progress;
    if ((theirs.epoch ?? '') !== (ours.epoch ?? '')) return false;
    if (holdsAll(ours, theirs) && JSON.stringify(theirs.settings) === JSON.stringify(ours.settings)) return false;
    const merged = mergeProgress(ours, theirs);
    this.levels = reconcileLevels(merged.levels, this.playable);
    this.badges = merged.badges;
    this.settings = theirs.settings;
    this.log.adopt(merged.log);
    this.changed = true;
    return true;
  }
}
