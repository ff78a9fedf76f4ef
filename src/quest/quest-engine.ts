import type { Issue } from '../util/issue.ts';
import type { LabAction } from '../lab-state/lab-action.ts';
import type { LabState } from '../lab-state/lab-state.ts';
import type { Scene } from '../scene/scene.ts';
import { newVisit, pointsAwaitingObservation, stageInVisit, workableTask, type ActiveLevel } from './active-level.ts';
import type { EarnedBadge } from './badges.ts';
import { systemClock, type HintStep, type HowCompleted, type LoggedEvent, type OfferedStep, type QuestClock } from './event-log.ts';
import { APP_ONLY_ACTION } from './lab-action-schema.ts';
import { checkGoal, fitsGoal, isRightPrediction, NO_EVENTS, tallyAction, touchesGoal, type Prediction } from './goal-check.ts';
import { kindOfGoal, predictionOf, predictionParts, type PictureGoal } from './goal.ts';
import { pictureScenes } from './picture-scenes.ts';
import { predictionRevealedBy, type PredictionStage } from './prediction-stage.ts';
import { canShowMe, climb, nextHintStep, NO_HINTS } from './hint-ladder.ts';
import { currentTask, isCompleted, isPassed, requiredTaskIds, type RequiredTasks } from './level-gate.ts';
import { levelMap, statusOfLevel, type ChapterMapView, type LevelStatus } from './level-map.ts';
import { playableLevels, type LevelCatalog } from './level-index.ts';
import type { Level, Task } from './level-schema.ts';
import { pointsOf, type Progress, type QuestSettings } from './progress.ts';
import { levelBadgesEarned, pointsFor, starsEarned } from './scoring.ts';
import type { Stars } from './challenge-par.ts';
import { comparisonEvent } from './challenge-progress.ts';
import { codeRunEvent } from './code-run-event.ts';
import { KeptProgress, type QuestListener } from './kept-progress.ts';
import { levelViewOf, type LevelView, type ViewSources } from './level-view.ts';

/**
 * The game's rules, with no DOM: which level is open, which task is the learner's, when a
 * task is done, points, badges, the gate and the hint ladder, all logged.
 *
 * It is fed by the store (`store.subscribe(engine.observe)`: the state and the action that
 * produced it) and by the task panel's calls (next, predict, reflect, continueAfterReveal,
 * askHint, showMe, skip, expandExplanation). It never dispatches: "show me" returns the actions for the UI to
 * perform visibly, through the store, where the engine sees them like any other.
 * Listeners hear about every change, with the events it logged.
 */

/** Idle time on a task before its first hint is offered: soon enough to come before
 * frustration, late enough not to interrupt someone reading or trying. The offer only says
 * a hint is ready; the learner may be thinking, so it costs nothing unless opened. */
export const IDLE_HINT_MS = 45_000;

export interface QuestEngineOptions {
  catalog: LevelCatalog;
  /** From ProgressStore.load(); the engine continues its event log with a new session. */
  progress: Progress;
  clock?: QuestClock;
  /** A teacher's assignment; by default each level requires its mandatory tasks. */
  requiredTasks?: RequiredTasks;
  idleHintMs?: number;
  /** This page load's id in event ids (event-log.ts); random by default. */
  session?: string;
}

/** What "show me" performs: the solution's actions, one by one through the store; or a quiz's answer (a choice's position, or an estimate's number). */
export type ShowMe = { kind: 'actions'; actions: LabAction[] } | { kind: 'answer'; answer: number };

export type OpenLevelResult = { ok: true; level: Level; scene: Scene } | { ok: false; reason: 'unknown' | 'broken' | 'locked' };

export class QuestEngine {
  private readonly catalog: LevelCatalog;
  private readonly levels: Level[];
  private readonly assignment: RequiredTasks | undefined;
  private readonly idleHintMs: number;
  private readonly kept: KeptProgress;
  private active: ActiveLevel | null = null;
  private lastState: LabState | null = null;
  private lastActivity: number;
  private visible = true;
  private readonly pictureCache = new WeakMap<PictureGoal, readonly Scene[]>();

  constructor(options: QuestEngineOptions) {
    this.catalog = options.catalog;
    this.levels = playableLevels(options.catalog);
    this.assignment = options.requiredTasks;
    this.idleHintMs = options.idleHintMs ?? IDLE_HINT_MS;
    this.kept = new KeptProgress(options.progress, this.levels, options.clock ?? systemClock, options.session);
    this.lastActivity = this.kept.log.now();
  }

  // ─── Reading ───────────────────────────────────────────────────────────────

  /** Everything to save; the event log inside is shared and only ever grows. */
  get progress(): Progress {
    return this.kept.progress;
  }

  /** The learner's points, less those of the open level's predictions still waiting for their observation (active-level.ts). */
  get points(): number {
    const active = this.active;
    return pointsOf(this.progress) - (active ? pointsAwaitingObservation(active, this.kept.levels[active.level.id]) : 0);
  }

  get badges(): readonly EarnedBadge[] {
    return this.kept.badges;
  }

  get events(): readonly LoggedEvent[] {
    return this.kept.log.events;
  }

  /** The level being played, or null on the level map. */
  get level(): LevelView | null {
    const active = this.active;
    return active && levelViewOf(this.viewSources(active), active);
  }

  /** The level map: chapters, each level's lock, tick and points; broken levels with their reasons. */
  map(): ChapterMapView[] {
    return levelMap(this.catalog, this.kept.levels, this.assignment);
  }

  levelStatus(id: string): LevelStatus {
    return statusOfLevel(this.catalog, this.kept.levels, this.assignment, id);
  }

  subscribe(listener: QuestListener): () => void {
    return this.kept.subscribe(listener);
  }

  // ─── Levels ────────────────────────────────────────────────────────────────

  /**
   * Opens a level that is not locked. Returns the scene to load into the store: the one the
   * learner left when resuming this level, else the level's own. The engine checks goals
   * from the first state the store reports after that.
   */
  openLevel(id: string): OpenLevelResult {
    const level = this.levels.find((candidate) => candidate.id === id);
    if (!level) return { ok: false, reason: this.catalog.chapters.some((chapter) => chapter.entries.some((entry) => entry.id === id)) ? 'broken' : 'unknown' };
    if (this.levelStatus(id) === 'locked') return { ok: false, reason: 'locked' };
    this.closeLevel();
    const sceneKept = this.kept.resumable?.level === id;
    const scene = sceneKept && this.kept.resumable ? this.kept.resumable.scene : level.scene;
    this.kept.resumable = { level: id, scene };
    this.lastState = null;
    const active = newVisit(level, requiredTaskIds(level, this.assignment), sceneKept);
    this.active = active;
    this.kept.append({ type: 'level.opened', level: id });
    // Tasks that are not required can be done any time: they are all shown at once.
    for (const task of level.tasks) {
      if (active.required.has(task.id) || isCompleted(this.kept.levels[id], task.id)) continue;
      active.tallies.set(task.id, NO_EVENTS);
      this.kept.append({ type: 'task.shown', level: id, task: task.id, mandatory: task.mandatory, required: false, kind: kindOfGoal(task.goal) });
    }
    this.showCurrentTask(active);
    this.kept.publish();
    return { ok: true, level, scene };
  }

  /** Back to the level map. The level's scene is remembered for when the learner returns. */
  closeLevel(): void {
    if (!this.active) return;
    this.kept.append({ type: 'level.closed', level: this.active.level.id });
    this.active = null;
    this.kept.publish();
  }

  // ─── Fed by the store ──────────────────────────────────────────────────────

  /**
   * The store's listener: a refused action (error) changed nothing and counts for nothing. A
   * live action (a value passed while dragging) starts tasks but completes none: "set it to 4"
   * is met by the value the learner lets go at, not by one the slider passed on its way to 6.
   */
  readonly observe = (state: LabState, action: LabAction, error?: readonly Issue[], live = false): void => {
    if (error !== undefined) return;
    this.lastActivity = this.kept.log.now();
    const levelId = this.active?.level.id ?? null;
    if (action.type === 'render.started') this.kept.append({ type: 'render.started', level: levelId });
    if (action.type === 'challenge.compared') this.kept.append(comparisonEvent(this.active, action));
    if (action.type === 'code.graded') this.kept.append(codeRunEvent(this.active?.level ?? null, action));
    if (action.type === 'render.finished') {
      this.kept.append({ type: 'render.finished', level: levelId, ms: action.ms });
      this.kept.award({ kind: 'first-render' });
    }
    const active = this.active;
    if (active) {
      if (this.kept.resumable?.scene !== state.scene) {
        this.kept.resumable = { level: active.level.id, scene: state.scene };
        this.kept.changed = true;
      }
      const before = this.lastState;
      this.lastState = state;
      // A declared view is the app's doing: it neither starts a task nor counts towards one.
      if (action.type === APP_ONLY_ACTION) return this.kept.publish();
      for (const [taskId, tally] of [...active.tallies]) {
        const task = active.level.tasks.find((candidate) => candidate.id === taskId);
        // A task completed by an earlier one in this loop (the next current task) is no longer watched.
        if (!task || !active.tallies.has(taskId) || kindOfGoal(task.goal) !== 'do') continue;
        if (touchesGoal(task.goal, before, state, action)) this.startOptional(active, taskId);
        if (live) continue;
        const next = tallyAction(task.goal, tally, state, action);
        active.tallies.set(taskId, next);
        if (!checkGoal(task.goal, state, next)) continue;
        const how = active.shownByApp.has(taskId) ? 'shown' : 'done';
        // A challenge matched by the learner keeps its golf score; one shown by "show me" earns none.
        this.complete(active, task, how, undefined, how === 'done' ? starsEarned(task.goal, action) : undefined);
      }
    }
    this.kept.publish();
  };

  // ─── The task panel ────────────────────────────────────────────────────────

  /** Completes the current task when it is an info step. */
  next(): boolean {
    const active = this.active;
    const task = active?.current;
    if (!active || !task || kindOfGoal(task.goal) !== 'info') return false;
    this.complete(active, task, 'done');
    this.kept.publish();
    return true;
  }

  /**
   * Records a prediction (a quiz's choice or an estimate's number), right or wrong, and
   * completes the task. Whether it was right is shown only after the observation.
   */
  predict(taskId: string, prediction: Prediction): { correct: boolean } | undefined {
    const found = this.workableTask(taskId);
    const goal = found && predictionOf(found.task.goal);
    if (!found || !goal || !fitsGoal(goal, prediction)) return undefined;
    const { active, task } = found;
    const correct = isRightPrediction(goal, prediction);
    this.lastActivity = this.kept.log.now();
    this.startOptional(active, taskId);
    this.kept.append({ type: 'quiz.answered', level: active.level.id, task: taskId, ...prediction, correct });
    this.complete(active, task, 'done', correct);
    this.kept.publish();
    return { correct };
  }

  /** After observing, a learner whose prediction was wrong says what they see now. */
  reflect(taskId: string, prediction: Prediction): { correct: boolean } | undefined {
    const active = this.active;
    const task = active?.level.tasks.find((candidate) => candidate.id === taskId);
    const goal = task && predictionOf(task.goal);
    if (!active || !task || !goal || this.stageOf(active, task) !== 'reflect' || !fitsGoal(goal, prediction)) return undefined;
    const correct = isRightPrediction(goal, prediction);
    this.lastActivity = this.kept.log.now();
    active.reveal = { quiz: taskId, reflection: prediction };
    this.kept.append({ type: 'quiz.reflected', level: active.level.id, task: taskId, ...prediction, correct });
    this.kept.publish();
    return { correct };
  }

  /** The learner has read a revealed prediction's explanation and moves on to the next task. */
  continueAfterReveal(taskId: string): boolean {
    const active = this.active;
    const task = active?.level.tasks.find((candidate) => candidate.id === taskId);
    if (!active || !task || this.stageOf(active, task) !== 'explain') return false;
    this.lastActivity = this.kept.log.now();
    active.reveal = null;
    this.kept.append({ type: 'quiz.explained', level: active.level.id, task: taskId });
    if (!active.current) this.showCurrentTask(active);
    this.kept.publish();
    return true;
  }

  /**
   * Climbs the task's hint ladder one rung: the next text hint, else the ring on its guide.
   * When that rung was offered after idle time, this opens the offer. Either way the learner
   * asked: the hint counts as used. Returns the rung shown, or undefined when only "show me"
   * (or nothing) is left.
   */
  askHint(taskId: string): OfferedStep | undefined {
    const found = this.workableTask(taskId);
    if (!found) return undefined;
    const { active, task } = found;
    const hints = active.hints.get(taskId) ?? NO_HINTS;
    const step = nextHintStep(task, hints);
    if (step !== 'text' && step !== 'guidance') return undefined;
    this.startOptional(active, taskId);
    const trigger = active.offered.delete(taskId) ? 'offered' : 'asked';
    active.hints.set(taskId, climb(hints, step));
    if (step === 'guidance' && task.guide) active.ring = { task: taskId, target: task.guide };
    this.hintShown(active, task, step, trigger);
    this.kept.publish();
    return step;
  }

  /**
   * The last rung: returns the solution's actions for the UI to perform, visibly, through the
   * store; the task then completes as shown. For a quiz, reveals the answer and completes it
   * as shown at once.
   */
  showMe(taskId: string): ShowMe | undefined {
    const found = this.workableTask(taskId);
    if (!found || !canShowMe(found.task)) return undefined;
    const { active, task } = found;
    this.startOptional(active, taskId);
    this.hintShown(active, task, 'show-me', 'asked');
    let shown: ShowMe | undefined;
    const goal = predictionOf(task.goal);
    if (goal) {
      this.complete(active, task, 'shown');
      shown = { kind: 'answer', answer: predictionParts(goal).answer };
    } else if (task.solution) {
      active.shownByApp.add(taskId);
      shown = { kind: 'actions', actions: task.solution };
    }
    this.kept.publish();
    return shown;
  }

  /** Leaves out a task that is not required (no points). */
  skip(taskId: string): boolean {
    const found = this.workableTask(taskId);
    if (!found || found.active.required.has(taskId)) return false;
    this.startOptional(found.active, taskId);
    this.complete(found.active, found.task, 'skipped');
    this.kept.publish();
    return true;
  }

  /** "Explain more" was opened, for a task or the level's intro. */
  expandExplanation(taskId: string | 'intro'): void {
    const active = this.active;
    if (!active || (taskId !== 'intro' && !active.level.tasks.some((task) => task.id === taskId))) return;
    this.lastActivity = this.kept.log.now();
    if (taskId !== 'intro') this.startOptional(active, taskId);
    this.kept.append({ type: 'explanation.expanded', level: active.level.id, task: taskId === 'intro' ? null : taskId });
    this.kept.publish();
  }

  // ─── Time and attention ────────────────────────────────────────────────────

  /**
   * Called by the UI's timer: after idle time on the current task, before any of its hints,
   * offers its first rung, once per visit. Nothing is shown and nothing counts as used until
   * the learner opens it (askHint). An info step is read, not done: the task card has no
   * hints for it, so nothing is offered there.
   */
  tick(): void {
    const active = this.active;
    const task = active?.current;
    if (!active || !task || !this.visible || kindOfGoal(task.goal) === 'info' || active.offered.has(task.id) || active.hints.has(task.id)) return;
    if (this.kept.log.now() - this.lastActivity < this.idleHintMs) return;
    const step = nextHintStep(task, NO_HINTS);
    if (step !== 'text' && step !== 'guidance') return;
    active.offered.add(task.id);
    this.kept.append({ type: 'hint.offered', level: active.level.id, task: task.id, step });
    this.kept.publish();
  }

  /** The tab was hidden or shown (document.visibilitychange, pagehide): active time leaves out hidden time. */
  visibilityChanged(visible: boolean): void {
    if (visible === this.visible) return;
    this.visible = visible;
    this.kept.append({ type: visible ? 'tab.visible' : 'tab.hidden' });
    // Time away is not time stuck on the task.
    if (visible) this.lastActivity = this.kept.log.now();
    this.kept.publish();
  }

  // ─── Other progress ────────────────────────────────────────────────────────

  saveSandbox(scene: Scene): void {
    this.kept.sandbox = scene;
    this.kept.changed = true;
    this.kept.award({ kind: 'sandbox-saved' });
    this.kept.publish();
  }

  changeSettings(changes: Partial<QuestSettings>): void {
    this.kept.settings = { ...this.kept.settings, ...changes };
    this.kept.changed = true;
    this.kept.publish();
  }

  /**
   * Takes in what another tab saved (kept-progress.ts). The open level moves on when its
   * current task was completed there. Returns false, and tells no one, when there was nothing
   * new; progress of a later epoch (a reset or import there) is not merged: the caller
   * replaces the engine.
   */
  absorb(theirs: Progress): boolean {
    if (!this.kept.absorb(theirs)) return false;
    const active = this.active;
    if (active) {
      for (const taskId of [...active.tallies.keys()]) if (isCompleted(this.kept.levels[active.level.id], taskId)) active.tallies.delete(taskId);
      if (active.current && isCompleted(this.kept.levels[active.level.id], active.current.id)) this.showCurrentTask(active);
    }
    this.kept.publish();
    return true;
  }

  // ─── Rules ─────────────────────────────────────────────────────────────────

  /** The open level and the task, if the learner can work on it now (active-level.ts). */
  private workableTask(taskId: string): { active: ActiveLevel; task: Task } | undefined {
    const active = this.active;
    const task = active && workableTask(active, this.kept.levels[active.level.id], taskId);
    return active && task ? { active, task } : undefined;
  }

  /** Makes the first required task not yet done the current one, and completes it at once if its goal already holds. */
  private showCurrentTask(active: ActiveLevel): void {
    const { level } = active;
    const task = currentTask(level, this.kept.levels[level.id], active.required);
    active.current = task;
    if (!task) return;
    active.tallies.set(task.id, NO_EVENTS);
    this.lastActivity = this.kept.log.now();
    this.kept.append({ type: 'task.shown', level: level.id, task: task.id, mandatory: task.mandatory, required: true, kind: kindOfGoal(task.goal) });
    // A learner who already did what the task asks (say, set supersampling to 2 earlier) is not made to do it again.
    if (this.lastState && kindOfGoal(task.goal) === 'do' && checkGoal(task.goal, this.lastState, NO_EVENTS)) {
      this.complete(active, task, active.shownByApp.has(task.id) ? 'shown' : 'done');
    }
  }

  private complete(active: ActiveLevel, task: Task, how: HowCompleted, correct?: boolean, stars?: Stars): void {
    const { level, required } = active;
    const before = this.kept.levelOf(level.id);
    const wasPassed = isPassed(level, before, required);
    const points = pointsFor(task, how, correct, stars);
    const scored = { ...(correct === undefined ? {} : { correct }), ...(stars === undefined ? {} : { stars }) };
    const record = { tasks: { ...before.tasks, [task.id]: { how, points, ...scored } }, hintsUsed: before.hintsUsed };
    this.kept.levels = { ...this.kept.levels, [level.id]: record };
    active.tallies.delete(task.id);
    if (active.ring?.task === task.id) active.ring = null;
    const isRequired = required.has(task.id);
    this.kept.append({
      type: 'task.completed',
      level: level.id,
      task: task.id,
      mandatory: task.mandatory,
      required: isRequired,
      how,
      points,
      ...(stars === undefined ? {} : { stars }),
    });

    if (isPassed(level, record, required) && !wasPassed) {
      this.kept.append({ type: 'level.passed', level: level.id });
      this.awardChapter(level.chapter);
    }
    for (const badge of levelBadgesEarned(level, record, required)) this.kept.award(badge);
    const revealed = how === 'skipped' ? undefined : predictionRevealedBy(level, required, record, task);
    if (revealed) active.reveal = { quiz: revealed.id };
    // A revealed prediction holds the level: the next task comes when the learner continues.
    if (active.current?.id === task.id) {
      if (revealed) active.current = undefined;
      else this.showCurrentTask(active);
    }
  }

  private stageOf(active: ActiveLevel, task: Task): PredictionStage {
    return stageInVisit(active, this.kept.levels[active.level.id], task);
  }

  /** What the task panel's views are read from (level-view.ts). */
  private viewSources(active: ActiveLevel): ViewSources {
    return {
      record: this.kept.levels[active.level.id],
      events: this.kept.log.events,
      logStart: this.kept.log.data.startedAt,
      pictures: (goal) => this.picturesOf(active.level, goal),
    };
  }

  /** A picture prediction's scenes, made once per level file (the UI caches their renders by scene). */
  private picturesOf(level: Level, goal: PictureGoal): readonly Scene[] {
    let scenes = this.pictureCache.get(goal);
    if (!scenes) this.pictureCache.set(goal, (scenes = pictureScenes(level.scene, goal)));
    return scenes;
  }

  /**
   * Logs the learner's first move towards an optional task in this visit: its time runs
   * from here (spec/classroom.md), so a task nobody touched is not timed at all.
   */
  private startOptional(active: ActiveLevel, taskId: string): void {
    if (active.required.has(taskId) || active.started.has(taskId) || isCompleted(this.kept.levels[active.level.id], taskId)) return;
    active.started.add(taskId);
    this.kept.append({ type: 'task.started', level: active.level.id, task: taskId });
  }

  /** A rung the learner opened: it counts against the level's "No hints needed" badge. */
  private hintShown(active: ActiveLevel, task: Task, step: HintStep, trigger: 'asked' | 'offered'): void {
    const { level } = active;
    const before = this.kept.levelOf(level.id);
    this.kept.levels = { ...this.kept.levels, [level.id]: { ...before, hintsUsed: before.hintsUsed + 1 } };
    this.lastActivity = this.kept.log.now();
    this.kept.append({ type: 'hint.shown', level: level.id, task: task.id, step, trigger });
  }

  private awardChapter(chapterId: string): void {
    const chapter = this.catalog.chapters.find((candidate) => candidate.id === chapterId);
    const levels = chapter?.entries.flatMap((entry) => (entry.ok ? [entry.level] : [])) ?? [];
    if (levels.every((level) => isPassed(level, this.kept.levels[level.id], requiredTaskIds(level, this.assignment)))) {
      this.kept.award({ kind: 'chapter-done', chapter: chapterId });
    }
  }
}
