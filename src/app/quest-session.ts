import type { Assignment } from '../classroom/assignment.ts';
import { systemClock, type QuestClock } from '../quest/event-log.ts';
import { playableLevels, type LevelCatalog } from '../quest/level-index.ts';
import type { Locale } from '../quest/localized-text.ts';
import { saveProblemText } from '../i18n/progress-problem-text.ts';
import { exportProgress, parseProgressJson, PROGRESS_KEY, ProgressStore, replacing, type KeyValueStorage, type ProgressProblem } from '../quest/progress-store.ts';
import { holdsAll } from '../quest/progress-merge.ts';
import type { Progress } from '../quest/progress.ts';
import { QuestEngine, type OpenLevelResult } from '../quest/quest-engine.ts';
import { defaultScene } from '../scene/scene-defaults.ts';
import type { Scene } from '../scene/scene.ts';
import { assignmentProgressKey } from '../classroom/assignment-id.ts';
import { isUuid, randomUuid } from '../classroom/learner-identity.ts';
import { assignmentCatalog } from './assignment-catalog.ts';
import { playShowMe, showMeSteps, type ShowMeStage } from './show-me-player.ts';
import type { Store } from '../lab-state/store.ts';
import type { LabState } from '../lab-state/lab-state.ts';
import { TaskViews } from './task-views.ts';

/**
 * The game's controller: ties the store (the lab), the quest engine (the rules) and the
 * progress store (localStorage) together, and tells the UI when anything changed.
 *
 * - Every store action goes to the engine; every engine change is saved at once.
 * - Opening a level loads its scene (or the one the learner left) with `scene.loaded`, then
 *   applies its declared view, and each task's view when it becomes current (task-views.ts).
 * - The free lab plays the sandbox scene, saved as the learner edits it.
 * - An assignment gets its own catalog, required tasks, locale and progress key.
 * - A participant code and the playthrough's attempt id live next to the progress, in
 *   `<progress key>.context` (see `readSessionContext`), where the classroom's exports read them.
 * - With an assignment that asks for a participant code, nothing starts (no level, no
 *   timing) until the code is given: the time spent typing it is no task's time.
 * - Other tabs of the game share the saved progress: every save merges with theirs, and
 *   when another tab saves (the window's `storage` event, see `attach`) this one takes in
 *   what it did and shows it, and writes back what the other tab's save lacked.
 * - Storage that cannot be written is found at once: the session saves when it starts, so
 *   `saveError` says so on every page load while the trouble lasts.
 */

/** `finished`: an assignment all passed, reopened: its closing screen (the survey, then the end) instead of a level. */
export type SessionMode = { kind: 'map' } | { kind: 'level'; id: string } | { kind: 'free-lab' } | { kind: 'finished' };

/** What the session keeps besides progress, for the classroom's exports. */
export interface SessionContext {
  participantCode: string | null;
  /** This playthrough's random id (learner-identity.ts); null only in a context saved before attempts had ids. */
  attemptId: string | null;
}

export interface QuestSessionOptions {
  store: Store;
  catalog: LevelCatalog;
  storage: KeyValueStorage;
  assignment?: Assignment | null;
  clock?: QuestClock;
  idleHintMs?: number;
}

/** The free lab keeps the learner's scene once it has rested this long (a drag is many changes). */
const SANDBOX_SAVE_MS = 1000;

export function sessionContextKey(progressKey: string): string {
  return `${progressKey}.context`;
}

/** The participant code and such saved with the progress under `progressKey`. */
export function readSessionContext(storage: KeyValueStorage, progressKey: string): SessionContext {
  try {
    const value: unknown = JSON.parse(storage.getItem(sessionContextKey(progressKey)) ?? 'null');
    const code = typeof value === 'object' && value !== null && 'participantCode' in value ? value.participantCode : null;
    const attempt = typeof value === 'object' && value !== null && 'attemptId' in value ? value.attemptId : null;
    return { participantCode: typeof code === 'string' ? code : null, attemptId: isUuid(attempt) ? attempt : null };
  } catch {
    return { participantCode: null, attemptId: null };
  }
}

export class QuestSession {
  readonly catalog: LevelCatalog;
  readonly assignment: Assignment | null;
  readonly progressKey: string;
  /** Why saved progress could not be used when the session started (for a message), if it could not. */
  readonly problem: ProgressProblem | undefined;
  private engineNow: QuestEngine;
  private modeNow: SessionMode = { kind: 'map' };
  private readonly store: Store;
  private readonly storage: KeyValueStorage;
  private readonly progress: ProgressStore;
  private readonly clock: QuestClock;
  private readonly idleHintMs: number | undefined;
  private readonly listeners = new Set<() => void>();
  private readonly cleanup: (() => void)[] = [];
  private stopEngine: () => void = () => {};
  private stopShowMe: () => void = () => {};
  private readonly views = new TaskViews();
  private sandboxTimer: ReturnType<typeof setTimeout> | undefined;
  private pendingSandbox: Scene | null = null;
  private lastSaveError: string | null = null;
  private contextNow: SessionContext;
  /** `start` was called while the participant code was still needed: it runs again when the code is given. */
  private waitingForCode = false;

  constructor(options: QuestSessionOptions) {
    this.store = options.store;
    this.storage = options.storage;
    this.clock = options.clock ?? systemClock;
    this.idleHintMs = options.idleHintMs;
    this.assignment = options.assignment ?? null;
    this.catalog = this.assignment ? assignmentCatalog(options.catalog, this.assignment) : options.catalog;
    this.progressKey = this.assignment ? assignmentProgressKey(this.assignment) : PROGRESS_KEY;
    this.progress = new ProgressStore(this.storage, this.clock, this.progressKey);
    this.contextNow = readSessionContext(this.storage, this.progressKey);
    if (this.contextNow.attemptId === null) this.saveContext({ ...this.contextNow, attemptId: randomUuid() });
    const loaded = this.progress.load();
    this.problem = loaded.problem;
    this.engineNow = this.makeEngine(loaded.progress);
    this.listenTo(this.engineNow);
    if (this.assignment && this.engineNow.progress.settings.locale !== this.assignment.locale) {
      this.engineNow.changeSettings({ locale: this.assignment.locale });
    } else {
      this.save();
    }
    this.applyPalette();
    this.cleanup.push(this.store.subscribe((state, action, error, live) => {
      this.engineNow.observe(state, action, error, live);
      this.keepPalette(state);
      if (this.modeNow.kind === 'free-lab' && action.type !== 'scene.loaded') this.keepSandbox(state.scene);
    }));
  }

  get engine(): QuestEngine {
    return this.engineNow;
  }

  get mode(): SessionMode {
    return this.modeNow;
  }

  get locale(): Locale {
    return this.engineNow.progress.settings.locale;
  }

  get context(): SessionContext {
    return this.contextNow;
  }

  /** The last reason progress could not be saved, until a save works again. */
  get saveError(): string | null {
    return this.lastSaveError;
  }

  /** Whether the start should ask for a participant code (an assignment that wants one, none given yet). */
  get needsParticipantCode(): boolean {
    return (this.assignment?.askParticipantCode ?? false) && this.contextNow.participantCode === null;
  }

  /** Every playable level of the assignment (or the game) passed. */
  get allPassed(): boolean {
    const levels = playableLevels(this.catalog).filter((level) => !this.assignment || this.assignment.levels.includes(level.id));
    return levels.length > 0 && levels.every((level) => this.engineNow.levelStatus(level.id) === 'passed');
  }

  subscribe(listener: () => void): () => void {
    this.listeners.add(listener);
    return () => this.listeners.delete(listener);
  }

  /**
   * Where to start: the level the learner was playing; else, for a newcomer who has done
   * nothing yet, the first level; else the map. Waits (on the map, behind the code dialog)
   * while a participant code is needed; a finished assignment opens on its closing screen.
   */
  start(): SessionMode {
    if (this.needsParticipantCode) {
      this.waitingForCode = true;
      this.openMap();
      return this.modeNow;
    }
    // A finished assignment reopens on its closing screen, not on its last level: that
    // would start a new visit (and new optional task attempts) in the log.
    if (this.assignment && this.allPassed) {
      this.leaveMode();
      this.engineNow.closeLevel();
      this.modeNow = { kind: 'finished' };
      this.notify();
      return this.modeNow;
    }
    const progress = this.engineNow.progress;
    const resume = progress.current?.level;
    if (resume && this.engineNow.levelStatus(resume) !== 'locked' && this.openLevel(resume).ok) return this.modeNow;
    const first = playableLevels(this.catalog)[0];
    if (first && Object.keys(progress.levels).length === 0 && this.openLevel(first.id).ok) return this.modeNow;
    this.openMap();
    return this.modeNow;
  }

  openLevel(id: string): OpenLevelResult {
    this.leaveMode();
    const opened = this.engineNow.openLevel(id);
    if (opened.ok) {
      this.modeNow = { kind: 'level', id };
      this.store.dispatch({ type: 'scene.loaded', scene: opened.scene });
      const view = this.views.opened(opened.level, this.engineNow.level?.current?.task ?? null);
      if (view) this.store.dispatch(view);
    }
    this.notify();
    return opened;
  }

  /** The map: the level's scene stays in the lab behind it, and is remembered for when the learner comes back. */
  openMap(): void {
    this.leaveMode();
    this.engineNow.closeLevel();
    this.modeNow = { kind: 'map' };
    this.notify();
  }

  /** The free lab: every panel, the learner's own saved scene (or the default one). */
  openFreeLab(): void {
    this.leaveMode();
    this.engineNow.closeLevel();
    this.modeNow = { kind: 'free-lab' };
    this.store.dispatch({ type: 'scene.loaded', scene: this.engineNow.progress.sandbox ?? defaultScene() });
    this.notify();
  }

  /** The next playable level after the open one, if there is one and it is open. */
  nextLevel(): string | undefined {
    const mode = this.modeNow;
    if (mode.kind !== 'level') return undefined;
    const levels = playableLevels(this.catalog);
    const next = levels[levels.findIndex((level) => level.id === mode.id) + 1];
    return next && this.engineNow.levelStatus(next.id) !== 'locked' ? next.id : undefined;
  }

  /**
   * "Show me" for a task: a quiz's answer is revealed by the engine; a solution is played
   * on `stage`, visibly, one step at a time.
   */
  showMe(taskId: string, stage: ShowMeStage): void {
    const shown = this.engineNow.showMe(taskId);
    if (shown?.kind !== 'actions') return;
    this.stopShowMe();
    this.stopShowMe = playShowMe(showMeSteps(shown.actions), stage);
  }

  setLocale(locale: Locale): void {
    this.engineNow.changeSettings({ locale });
  }

  /** The learner's code; a start that waited for it (see `start`) goes on now. */
  setParticipantCode(code: string): void {
    this.saveContext({ ...this.contextNow, participantCode: code });
    if (this.waitingForCode) {
      this.waitingForCode = false;
      this.start();
    }
    this.notify();
  }

  /** The text of a progress file to download. */
  exportText(): string {
    return exportProgress(this.engineNow.progress);
  }

  /** Replaces the progress with an imported file's, when it is valid; the reasons when not (nothing changes then). */
  importText(text: string): { ok: true } | { ok: false; errors: string[] } {
    const parsed = parseProgressJson(text);
    if (!parsed.ok) return { ok: false, errors: parsed.errors };
    this.replaceEngine(this.makeEngine(replacing(parsed.progress, this.engineNow.progress, this.clock)));
    this.save();
    return { ok: true };
  }

  /** Forgets all progress (the UI has asked) and starts afresh on the map: a new attempt. */
  reset(): void {
    this.saveContext({ ...this.contextNow, attemptId: randomUuid() });
    this.replaceEngine(this.makeEngine(this.progress.reset(this.engineNow.progress)));
    this.save();
  }

  /**
   * Another tab wrote `key` (null: it cleared the storage): takes in its progress. A later
   * epoch (a reset or an import there) replaces ours; else the two merge, and what the
   * other tab's save lacked of ours is written back.
   */
  storageChanged(key: string | null): void {
    if (key !== null && key !== this.progressKey) return;
    const theirs = this.progress.read();
    if (theirs) this.takeIn(theirs); // when it brought news, the engine's listener saved the merge
    const saved = this.progress.read();
    if (!saved || !holdsAll(saved, this.engineNow.progress)) this.save();
  }

  /**
   * Follows the tab's visibility (hidden time is not idle time) and ticks the engine once a
   * second, only while a level is open and the tab is seen, so a hint can be offered after
   * idle time. Listens for other tabs' saves (`storage` events of this session's storage).
   */
  attach(document: Document): () => void {
    let timer: ReturnType<typeof setInterval> | undefined;
    const update = () => {
      const visible = document.visibilityState === 'visible';
      this.engineNow.visibilityChanged(visible);
      const ticking = visible && this.modeNow.kind === 'level';
      if (ticking && timer === undefined) timer = setInterval(() => this.engineNow.tick(), 1000);
      if (!ticking && timer !== undefined) {
        clearInterval(timer);
        timer = undefined;
      }
    };
    const unsubscribe = this.subscribe(update);
    document.addEventListener('visibilitychange', update);
    const onStorage = (event: StorageEvent) => {
      if (event.storageArea === this.storage) this.storageChanged(event.key);
    };
    const window = document.defaultView;
    window?.addEventListener('storage', onStorage);
    update();
    return () => {
      unsubscribe();
      document.removeEventListener('visibilitychange', update);
      window?.removeEventListener('storage', onStorage);
      clearInterval(timer);
    };
  }

  dispose(): void {
    this.leaveMode();
    this.stopEngine();
    for (const stop of this.cleanup.splice(0)) stop();
    this.listeners.clear();
  }

  private makeEngine(progress: QuestEngine['progress']): QuestEngine {
    return new QuestEngine({
      catalog: this.catalog,
      progress,
      clock: this.clock,
      ...(this.assignment ? { requiredTasks: this.assignment.requiredTasks } : {}),
      ...(this.idleHintMs === undefined ? {} : { idleHintMs: this.idleHintMs }),
    });
  }

  private listenTo(engine: QuestEngine): void {
    this.stopEngine();
    this.stopEngine = engine.subscribe(() => {
      this.save();
      this.notify();
      this.followTask();
    });
  }

  private replaceEngine(engine: QuestEngine): void {
    this.leaveMode();
    this.engineNow = engine;
    this.listenTo(engine);
    this.applyPalette();
    this.modeNow = { kind: 'map' };
    this.notify();
  }

  /**
   * Applies the view of a task that has just become current. The engine moves on while the
   * store is still telling its listeners about the action that completed the last task, so
   * the view waits for that to end: every listener then sees the two actions in order.
   */
  private followTask(): void {
    const level = this.engineNow.level;
    const view = this.views.changed(level?.level ?? null, level?.current?.task ?? null);
    if (view) queueMicrotask(() => this.store.dispatch(view));
  }

  /** Stops what belongs to the mode being left: a "show me" still playing, the sandbox not yet saved. */
  private leaveMode(): void {
    this.stopShowMe();
    this.views.closed();
    this.flushSandbox();
  }

  /**
   * The ray palette is the learner's setting, saved with the progress (the ray panel's switch
   * and the menu both change it through the store): a colour-blind learner chooses it once.
   */
  private keepPalette(state: LabState): void {
    const colorBlindPalette = state.rays.colorBlindPalette;
    if (colorBlindPalette !== this.engineNow.progress.settings.colorBlindPalette) this.engineNow.changeSettings({ colorBlindPalette });
  }

  /** The saved palette, into the lab (at the start, after an import or a reset). */
  private applyPalette(): void {
    const colorBlindPalette = this.engineNow.progress.settings.colorBlindPalette;
    if (this.store.state.rays.colorBlindPalette !== colorBlindPalette) this.store.dispatch({ type: 'rays.changed', changes: { colorBlindPalette } });
  }

  private saveContext(context: SessionContext): void {
    this.contextNow = context;
    try {
      this.storage.setItem(sessionContextKey(this.progressKey), JSON.stringify(context));
    } catch {
      // Kept for this visit; the progress save reports the storage problem.
    }
  }

  /** Saves, merged with other tabs' progress, and takes in what they had added. */
  private save(): void {
    const result = this.progress.save(this.engineNow.progress);
    this.lastSaveError = result.ok ? null : saveProblemText(result.kind);
    if (result.ok) this.takeIn(result.saved);
  }

  /** Progress saved by another tab joins ours (absorb tells the listeners, which saves again: the merge is then a no-op). */
  private takeIn(saved: Progress): void {
    if ((saved.epoch ?? '') > (this.engineNow.progress.epoch ?? '')) this.replaceEngine(this.makeEngine(saved));
    else this.engineNow.absorb(saved);
  }

  private keepSandbox(scene: Scene): void {
    clearTimeout(this.sandboxTimer);
    this.sandboxTimer = setTimeout(() => this.flushSandbox(), SANDBOX_SAVE_MS);
    this.pendingSandbox = scene;
  }

  private flushSandbox(): void {
    clearTimeout(this.sandboxTimer);
    if (this.pendingSandbox) this.engineNow.saveSandbox(this.pendingSandbox);
    this.pendingSandbox = null;
  }

  private notify(): void {
    for (const listener of [...this.listeners]) listener();
  }
}
