import type { Assignment } from '../classroom/assignment.ts';
import { systemClock, type QuestClock } from '../quest/event-log.ts';
import { playableLevels, type LevelCatalog } from '../quest/level-index.ts';
import type { Locale } from '../quest/localized-text.ts';
import {
  exportProgress,
  PROGRESS_KEY,
  ProgressStore,
  readProgressJson,
  replacing,
  type KeyValueStorage,
  type ProgressProblem,
  type SaveProblemKind,
} from '../quest/progress-store.ts';
import { holdsAll } from '../quest/progress-merge.ts';
import type { Progress } from '../quest/progress.ts';
import { keepLabCode, keptLabCode, type CodeNotImported } from '../quest/progress-lab-code.ts';
import { QuestEngine, type OpenLevelResult } from '../quest/quest-engine.ts';
import { defaultScene } from '../scene/scene-defaults.ts';
import { assignmentProgressKey } from '../classroom/assignment-id.ts';
import { randomUuid } from '../classroom/learner-identity.ts';
import { assignmentCatalog } from './assignment-catalog.ts';
import { ConceptTestKeeper } from './concept-test-keeper.ts';
import { DamagedSaves, withRestored } from './damaged-saves.ts';
import { applyPalette, keepPalette } from './palette-setting.ts';
import { PendingWrites } from './pending-writes.ts';
import { loadSessionContext, readContextText, sessionContextKey, type ContextDamage, type SessionContext } from './session-context.ts';
import { playShowMe, showMeSteps, type ShowMeStage } from './show-me-player.ts';
import type { Store } from '../lab-state/store.ts';
import type { Issue } from '../util/issue.ts';
import { SandboxSaver } from './sandbox-saver.ts';
import { attachToPage } from './session-page.ts';
import { SurveyKeeper } from './survey-keeper.ts';
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
 * - A participant code and the playthrough's attempt id live next to the progress
 *   (session-context.ts), where the classroom's exports read them.
 * - With an assignment that asks for a participant code, nothing starts (no level, no
 *   timing) until the code is given: the time spent typing it is no task's time.
 * - Other tabs of the game share the saved progress: every save merges with theirs, and
 *   when another tab saves (the window's `storage` event, see `attach`) this one takes in
 *   what it did and shows it, and writes back what the other tab's save lacked.
 * - Storage that cannot be written is found at once (the session saves when it starts) and
 *   said by `saveProblem` while it lasts. Nothing is lost meanwhile: the progress is in the
 *   engine, the session record and survey wait in `PendingWrites`, and every save (each
 *   change, leaving the page: `attach`) tries again. An import, a reset or a restore
 *   replaces the progress only once it is written. Damaged saves are listed for the Menu
 *   (`damagedSaves`) to download, restore or delete.
 */

/** `finished`: an assignment all passed, reopened: its closing screen (the survey, then the end) instead of a level. */
export type SessionMode = { kind: 'map' } | { kind: 'level'; id: string } | { kind: 'free-lab' } | { kind: 'finished' };

export interface QuestSessionOptions {
  store: Store;
  catalog: LevelCatalog;
  storage: KeyValueStorage;
  assignment?: Assignment | null;
  clock?: QuestClock;
  idleHintMs?: number;
}

export type ImportResult =
  | { ok: true; repaired: string[]; code?: CodeNotImported }
  | { ok: false; reason: 'unreadable'; errors: Issue[] }
  | { ok: false; reason: 'not-saved'; kind: SaveProblemKind };

export class QuestSession {
  readonly catalog: LevelCatalog;
  readonly assignment: Assignment | null;
  readonly progressKey: string;
  /** Why saved progress could not be used as it was when the session started (for a message), if it could not. */
  readonly problem: ProgressProblem | undefined;
  /** What of the saved session record (participant code, attempt) could not be read, if any. */
  readonly contextDamage: ContextDamage | null;
  /** The closing survey: its answers (kept in memory when they could not be written yet), a damaged record of them, handing in. */
  readonly survey: SurveyKeeper;
  /** The Menu's damaged saves of this progress key. */
  readonly damagedSaves: DamagedSaves;
  /** The assignment's concept test: its answers, the one due (the start waits for the one before), handing in. */
  readonly conceptTests: ConceptTestKeeper;
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
  private readonly sandbox: SandboxSaver;
  private saveProblemNow: SaveProblemKind | null = null;
  private readonly writes: PendingWrites;
  private contextNow: SessionContext;
  /** `start` was called while the participant code (or the concept test before) was needed: it runs again when given. */
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
    this.sandbox = new SandboxSaver(this.clock, (scene) => this.engineNow.saveSandbox(scene));
    this.writes = new PendingWrites(this.storage, () => this.clock.wallMs());
    const context = loadSessionContext(this.storage, this.progressKey, this.clock.wallMs());
    this.contextNow = context.context;
    this.contextDamage = context.damage;
    if (context.damage && context.damage.backupKey === null) this.writes.hold(sessionContextKey(this.progressKey), context.damage.raw);
    if (this.contextNow.attemptId === null) this.saveContext({ ...this.contextNow, attemptId: randomUuid() });
    this.survey = new SurveyKeeper(
      { progressKey: this.progressKey, save: () => this.save(), notify: () => this.notify() },
      this.writes,
      this.storage,
      this.clock.wallMs(),
    );
    this.conceptTests = new ConceptTestKeeper(this, this.writes, this.storage, this.clock.wallMs());
    const loaded = this.progress.load();
    this.problem = loaded.problem;
    this.damagedSaves = new DamagedSaves(this.storage, this.progress, this.writes, this.progressKey);
    this.engineNow = this.makeEngine(loaded.progress);
    this.listenTo(this.engineNow);
    if (this.assignment && this.engineNow.progress.settings.locale !== this.assignment.locale) {
      this.engineNow.changeSettings({ locale: this.assignment.locale });
    } else {
      this.save();
    }
    applyPalette(this.engineNow, this.store);
    this.cleanup.push(
      this.store.subscribe((state, action, error, live) => {
        this.engineNow.observe(state, action, error, live);
        keepPalette(this.engineNow, state);
        if (this.modeNow.kind !== 'free-lab') return;
        if (action.type === 'scene.loaded') this.sandbox.loaded(state.scene);
        else this.sandbox.keep(state.scene, live === true);
      }),
    );
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

  /** Why the last save failed (progress, session record or survey), until a save works again. */
  get saveProblem(): SaveProblemKind | null {
    return this.saveProblemNow;
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
    this.waitingForCode = this.needsParticipantCode || this.conceptTests.due === 'pre';
    if (this.waitingForCode) {
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
    this.changeContext({ ...this.contextNow, participantCode: code });
  }

  /** The text of a progress file to download, with the learner's code of each code lab. */
  exportText(): string {
    const code = keptLabCode(this.storage);
    return exportProgress({ ...this.engineNow.progress, ...(Object.keys(code).length > 0 ? { code } : {}) });
  }

  /**
   * Replaces the progress with an imported file's, its damaged parts left out (`repaired`),
   * and each lab's code with the file's (a lab's code that is refused stays as it was here).
   * Nothing changes when the file cannot be read or cannot be written to storage.
   */
  importText(text: string): ImportResult {
    const read = readProgressJson(text, new Date(this.clock.wallMs()).toISOString());
    if (!read.ok) return { ok: false, reason: 'unreadable', errors: read.errors };
    // The code is kept under keys of its own (progress-lab-code.ts), not in the saved progress.
    const { code, ...progress } = read.progress;
    const problem = this.replaceProgress(replacing(progress, this.engineNow.progress, this.clock));
    if (problem) return { ok: false, reason: 'not-saved', kind: problem };
    const refused = read.repaired.filter((note) => /^code[.:[]/.test(note));
    const notImported = { refused: refused.map(labOfNote), notSaved: keepLabCode(this.storage, code ?? {}) };
    const repaired = read.repaired.filter((note) => !refused.includes(note));
    return refused.length + notImported.notSaved.length > 0 ? { ok: true, repaired, code: notImported } : { ok: true, repaired };
  }

  /** Forgets all progress (the UI has asked) and starts afresh on the map: a new attempt. Null when done, else why not. */
  reset(): SaveProblemKind | null {
    const problem = this.replaceProgress(this.progress.reset(this.engineNow.progress));
    if (!problem) this.changeContext({ ...this.contextNow, attemptId: randomUuid() });
    return problem;
  }

  /** Saves nothing any more, so that data just deleted (withdraw-data.ts) does not come back before the page starts again. */
  readonly stopSaving = (): void => void (this.save = () => null);

  /**
   * Takes a damaged save's contents back: a progress backup's tasks, badges and events join
   * the progress (damaged-saves.ts withRestored); a session record's code and attempt come
   * back; survey and concept-test answers come back by their keepers. Its parts this version
   * cannot read are reported, and nothing changes when none can.
   */
  restoreBackup(key: string): ImportResult {
    const text = this.damagedSaves.text(key);
    if (text === null) return { ok: false, reason: 'unreadable', errors: [] };
    if (this.damagedSaves.what(key) === 'session') return this.restoreContext(text);
    if (this.damagedSaves.what(key) === 'survey') return this.survey.restore(text);
    if (this.damagedSaves.what(key) === 'concept-test') return this.conceptTests.restore(text);
    const read = readProgressJson(text, new Date(this.clock.wallMs()).toISOString());
    if (!read.ok) return { ok: false, reason: 'unreadable', errors: read.errors };
    const current = this.engineNow.progress;
    const problem = this.replaceProgress(replacing(withRestored(current, read.progress), current, this.clock));
    return problem ? { ok: false, reason: 'not-saved', kind: problem } : { ok: true, repaired: read.repaired };
  }

  /**
   * Saves what is not saved yet: the sandbox scene still resting, and writes that failed.
   * For leaving the page, and after the learner downloaded a held damaged save (damaged-saves.ts).
   */
  flush(): void {
    this.sandbox.flush();
    if (this.saveProblemNow !== null || this.writes.anyWaiting) this.save();
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

  /** Follows the page: visibility, idle ticks, other tabs' saves, leaving (session-page.ts). */
  attach(document: Document): () => void {
    return attachToPage(this, document, this.storage);
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
    applyPalette(this.engineNow, this.store);
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
    this.sandbox.flush();
  }

  /** The session record, written at the next save. */
  private saveContext(context: SessionContext): void {
    this.contextNow = context;
    this.writes.put(sessionContextKey(this.progressKey), JSON.stringify(context));
  }

  /** A new code or attempt, saved; a start that waited for the code goes on. */
  private changeContext(context: SessionContext): void {
    this.saveContext(context);
    this.save();
    if (this.waitingForCode && !this.needsParticipantCode) {
      this.waitingForCode = false;
      this.start();
    }
    this.notify();
  }

  /** A session record's backup: what can be read of its code and attempt replaces what is missing or new. */
  private restoreContext(text: string): ImportResult {
    const { context } = readContextText(text);
    if (context.participantCode === null && context.attemptId === null) return { ok: false, reason: 'unreadable', errors: [] };
    this.changeContext({
      participantCode: context.participantCode ?? this.contextNow.participantCode,
      attemptId: context.attemptId ?? this.contextNow.attemptId,
    });
    return { ok: true, repaired: [] };
  }

  /**
   * Saves, merged with other tabs' progress, and takes in what they had added; then writes
   * the session record and survey if they wait. Returns why a write failed, or null.
   */
  private save(): SaveProblemKind | null {
    const result = this.progress.save(this.engineNow.progress);
    const others = this.writes.flush();
    const held = this.damagedSaves.all.some((save) => save.held);
    this.saveProblemNow = result.ok ? others : result.kind;
    // A held damaged save may have been backed up by this save: the Menu's list follows.
    if (held) this.damagedSaves.refresh();
    if (result.ok) this.takeIn(result.saved);
    return this.saveProblemNow;
  }

  /**
   * An import, a reset or a restore: `candidate` (of a new epoch) is written first and
   * replaces the progress only when it is (a file too large for the storage changes nothing).
   */
  private replaceProgress(candidate: Progress): SaveProblemKind | null {
    this.sandbox.flush();
    const result = this.progress.save(candidate);
    if (!result.ok) return result.kind;
    this.replaceEngine(this.makeEngine(result.saved));
    this.save();
    return null;
  }

  /** Progress saved by another tab joins ours (absorb tells the listeners, which saves again: the merge is then a no-op). */
  private takeIn(saved: Progress): void {
    if ((saved.epoch ?? '') > (this.engineNow.progress.epoch ?? '')) this.replaceEngine(this.makeEngine(saved));
    else this.engineNow.absorb(saved);
  }

  private notify(): void {
    for (const listener of [...this.listeners]) listener();
  }
}

/** The lab a salvage note on the file's code is about (`code.<lab>: …`), or '' for all of it. */
function labOfNote(note: string): string {
  return note.slice(0, note.indexOf(':')).replace(/^code\.?/, '');
}
