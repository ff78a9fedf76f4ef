import type { Issue } from '../util/issue.ts';
import type { LabAction } from '../lab-state/lab-action.ts';
import type { LabState } from '../lab-state/lab-state.ts';
import type { Scene } from '../scene/scene.ts';
import { sameBadge, type Badge, type EarnedBadge } from './badges.ts';
import { EventLog, systemClock, type HintStep, type HowCompleted, type LoggedEvent, type OfferedStep, type QuestClock, type QuestEvent } from './event-log.ts';
import { APP_ONLY_ACTION } from './lab-action-schema.ts';
import { choiceOrder } from './choice-order.ts';
import { checkGoal, fitsGoal, isRightPrediction, NO_EVENTS, tallyAction, touchesGoal, type EventTally, type Prediction } from './goal-check.ts';
import { kindOfGoal, predictionOf, predictionParts, type PictureGoal, type TaskKind } from './goal.ts';
import { pictureScenes } from './picture-scenes.ts';
import { lastPrediction, observerOf, predictionRevealedBy, stageOf, type PredictionStage, type Reveal } from './prediction-stage.ts';
import { canShowMe, climb, nextHintStep, NO_HINTS, type HintProgress } from './hint-ladder.ts';
import type { GuideTarget } from './lab-controls.ts';
import { currentTask, isCompleted, isPassed, requiredTaskIds, type RequiredTasks } from './level-gate.ts';
import { levelMap, statusOfLevel, type ChapterMapView, type LevelStatus } from './level-map.ts';
import { playableLevels, type LevelCatalog } from './level-index.ts';
import type { Level, Task } from './level-schema.ts';
import type { LocalizedText } from './localized-text.ts';
import { pointsOf, PROGRESS_KIND, PROGRESS_VERSION, type LevelProgress, type Progress, type QuestSettings } from './progress.ts';
import { levelBadgesEarned, pointsFor, starsEarned } from './scoring.ts';
import type { Stars } from './challenge-par.ts';
import { matchScore } from './challenge-closeness.ts';
import { codeRunEvent } from './code-run-event.ts';
import { holdsAll, mergeProgress } from './progress-merge.ts';
import { reconcileLevels } from './progress-reconcile.ts';

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

/** A task's status: `current` is the required task to do now; `open` a task that is not
 * required and not done; `waiting` a required task after the current one. */
export type TaskStatus = 'current' | 'open' | 'waiting' | HowCompleted;

export interface PredictionView {
  stage: PredictionStage;
  /** A quiz's choices in the order this learner sees them (file positions); empty for a number. */
  order: number[];
  /** The learner's prediction, once made (from the log). */
  prediction?: Prediction;
  /** What a learner whose prediction was wrong said they saw. */
  reflection?: Prediction;
  /** The task whose result checks the prediction; none when the result is seen at once. */
  observer?: Task;
  /** A picture prediction's scenes to render, one per choice in file order. */
  pictures?: readonly Scene[];
}

export interface TaskView {
  task: Task;
  kind: TaskKind;
  required: boolean;
  status: TaskStatus;
  /** Points earned; 0 until completed. */
  points: number;
  /** For an answered quiz: whether the prediction was right. */
  correct?: boolean;
  /** For a challenge the learner matched: its golf score, as saved. */
  stars?: Stars;
  /** For a quiz or estimate: its stage, the order of its choices, the learner's prediction. */
  prediction?: PredictionView;
  /** For the task that checks a prediction, while it is to do: that prediction and its quiz. */
  checks?: { quiz: Task; prediction: Prediction; order: number[] };
  /** The text hints shown so far. */
  hints: LocalizedText[];
  /** What asking for help does next (`show-me`: offer the "Show me" button); null when nothing is left. */
  nextHint: HintStep | null;
  /** The app offered the next rung after idle time and the learner has not opened it yet. */
  hintOffered: boolean;
}

export interface LevelView {
  level: Level;
  tasks: TaskView[];
  /** The required task to do now; null once the level is passed, or while a prediction is revealed. */
  current: TaskView | null;
  /** The prediction being revealed after its observation (the learner continues from it), or null. */
  revealing: TaskView | null;
  /** The level opened with the scene the learner left it with, not its own (see openLevel). */
  sceneKept: boolean;
  passed: boolean;
  points: number;
  maxPoints: number;
  /** The control to ring: the guide of the last guidance shown, while its task is not done. */
  ring: GuideTarget | null;
}

/** What "show me" performs: the solution's actions, one by one through the store; or a quiz's answer (a choice's position, or an estimate's number). */
export type ShowMe = { kind: 'actions'; actions: LabAction[] } | { kind: 'answer'; answer: number };

export type OpenLevelResult = { ok: true; level: Level; scene: Scene } | { ok: false; reason: 'unknown' | 'broken' | 'locked' };

/** Called after every change, with the events it logged (none when only the scene or settings changed). */
export type QuestListener = (events: readonly LoggedEvent[]) => void;

/** The open level's state that lasts for this visit only. */
interface ActiveLevel {
  level: Level;
  required: ReadonlySet<string>;
  current: Task | undefined;
  /** Event goals matched since each watched task was shown. */
  tallies: Map<string, EventTally>;
  hints: Map<string, HintProgress>;
  /** Tasks whose first rung was offered after idle time (once per visit). */
  offered: Set<string>;
  /** Tasks whose "show me" was used: they complete as shown. */
  shownByApp: Set<string>;
  /** Optional tasks the learner has started on in this visit (`task.started` logged). */
  started: Set<string>;
  ring: { task: string; target: GuideTarget } | null;
  /** The prediction whose result was just observed: it holds the level until the learner continues. */
  reveal: Reveal | null;
  /** Opened with the scene the learner left, not the level's own. */
  sceneKept: boolean;
}

export class QuestEngine {
  private readonly catalog: LevelCatalog;
  private readonly levels: Level[];
  private readonly log: EventLog;
  private readonly assignment: RequiredTasks | undefined;
  private readonly idleHintMs: number;
  private levelProgress: Record<string, LevelProgress>;
  private earned: EarnedBadge[];
  private settings: QuestSettings;
  private sandbox: Scene | null;
  private resumable: Progress['current'];
  private readonly epoch: string | undefined;
  private active: ActiveLevel | null = null;
  private lastState: LabState | null = null;
  private lastActivity: number;
  private visible = true;
  private readonly listeners = new Set<QuestListener>();
  private unpublished: LoggedEvent[] = [];
  private changed = false;
  private readonly pictureCache = new WeakMap<PictureGoal, readonly Scene[]>();

  constructor(options: QuestEngineOptions) {
    this.catalog = options.catalog;
    this.levels = playableLevels(options.catalog);
    this.assignment = options.requiredTasks;
    this.idleHintMs = options.idleHintMs ?? IDLE_HINT_MS;
    const { progress } = options;
    this.levelProgress = reconcileLevels(progress.levels, this.levels);
    this.earned = progress.badges;
    this.settings = progress.settings;
    this.sandbox = progress.sandbox;
    this.resumable = progress.current;
    this.epoch = progress.epoch;
    this.log = new EventLog(progress.log, options.clock ?? systemClock, options.session);
    this.lastActivity = this.log.now();
  }

  // ─── Reading ───────────────────────────────────────────────────────────────

  /** Everything to save; the event log inside is shared and only ever grows. */
  get progress(): Progress {
    return {
      kind: PROGRESS_KIND,
      version: PROGRESS_VERSION,
      levels: this.levelProgress,
      badges: this.earned,
      settings: this.settings,
      sandbox: this.sandbox,
      current: this.resumable,
      log: this.log.data,
      ...(this.epoch === undefined ? {} : { epoch: this.epoch }),
    };
  }

  /**
   * The learner's points, less those of predictions in the open level still waiting for their
   * observation: a score that jumped at "lock in" would tell whether the prediction was right.
   */
  get points(): number {
    const active = this.active;
    const record = active && this.levelProgress[active.level.id];
    const waiting =
      !active || !record
        ? 0
        : active.level.tasks.reduce(
            (sum, task) => sum + (predictionOf(task.goal) && this.stageOf(active, task) === 'wait' ? (record.tasks[task.id]?.points ?? 0) : 0),
            0,
          );
    return pointsOf(this.progress) - waiting;
  }

  get badges(): readonly EarnedBadge[] {
    return this.earned;
  }

  get events(): readonly LoggedEvent[] {
    return this.log.events;
  }

  /** The level being played, or null on the level map. */
  get level(): LevelView | null {
    const active = this.active;
    if (!active) return null;
    const { level, required } = active;
    const record = this.levelProgress[level.id];
    const tasks = level.tasks.map((task) => this.taskView(active, task));
    return {
      level,
      tasks,
      current: tasks.find((view) => view.status === 'current') ?? null,
      revealing: tasks.find((view) => view.task.id === active.reveal?.quiz) ?? null,
      sceneKept: active.sceneKept,
      passed: isPassed(level, record, required),
      points: tasks.reduce((sum, view) => sum + view.points, 0),
      maxPoints: level.tasks.reduce((sum, task) => sum + task.points, 0),
      ring: active.ring?.target ?? null,
    };
  }

  /** The level map: chapters, each level's lock, tick and points; broken levels with their reasons. */
  map(): ChapterMapView[] {
    return levelMap(this.catalog, this.levelProgress, this.assignment);
  }

  levelStatus(id: string): LevelStatus {
    return statusOfLevel(this.catalog, this.levelProgress, this.assignment, id);
  }

  subscribe(listener: QuestListener): () => void {
    this.listeners.add(listener);
    return () => this.listeners.delete(listener);
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
    const sceneKept = this.resumable?.level === id;
    const scene = sceneKept && this.resumable ? this.resumable.scene : level.scene;
    this.resumable = { level: id, scene };
    this.lastState = null;
    const active: ActiveLevel = {
      level,
      required: requiredTaskIds(level, this.assignment),
      current: undefined,
      tallies: new Map(),
      hints: new Map(),
      offered: new Set(),
      shownByApp: new Set(),
      started: new Set(),
      ring: null,
      reveal: null,
      sceneKept,
    };
    this.active = active;
    this.append({ type: 'level.opened', level: id });
    // Tasks that are not required can be done any time: they are all shown at once.
    for (const task of level.tasks) {
      if (active.required.has(task.id) || isCompleted(this.levelProgress[id], task.id)) continue;
      active.tallies.set(task.id, NO_EVENTS);
      this.append({ type: 'task.shown', level: id, task: task.id, mandatory: task.mandatory, required: false, kind: kindOfGoal(task.goal) });
    }
    this.showCurrentTask(active);
    this.publish();
    return { ok: true, level, scene };
  }

  /** Back to the level map. The level's scene is remembered for when the learner returns. */
  closeLevel(): void {
    if (!this.active) return;
    this.append({ type: 'level.closed', level: this.active.level.id });
    this.active = null;
    this.publish();
  }

  // ─── Fed by the store ──────────────────────────────────────────────────────

  /**
   * The store's listener: a refused action (error) changed nothing and counts for nothing. A
   * live action (a value passed while dragging) starts tasks but completes none: "set it to 4"
   * is met by the value the learner lets go at, not by one the slider passed on its way to 6.
   */
  readonly observe = (state: LabState, action: LabAction, error?: readonly Issue[], live = false): void => {
    if (error !== undefined) return;
    this.lastActivity = this.log.now();
    const levelId = this.active?.level.id ?? null;
    if (action.type === 'render.started') this.append({ type: 'render.started', level: levelId });
    if (action.type === 'challenge.compared') this.append(comparisonEvent(this.active, action));
    if (action.type === 'code.graded') this.append(codeRunEvent(this.active?.level ?? null, action));
    if (action.type === 'render.finished') {
      this.append({ type: 'render.finished', level: levelId, ms: action.ms });
      this.award({ kind: 'first-render' });
    }
    const active = this.active;
    if (active) {
      if (this.resumable?.scene !== state.scene) {
        this.resumable = { level: active.level.id, scene: state.scene };
        this.changed = true;
      }
      const before = this.lastState;
      this.lastState = state;
      // A declared view is the app's doing: it neither starts a task nor counts towards one.
      if (action.type === APP_ONLY_ACTION) return this.publish();
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
    this.publish();
  };

  // ─── The task panel ────────────────────────────────────────────────────────

  /** Completes the current task when it is an info step. */
  next(): boolean {
    const active = this.active;
    const task = active?.current;
    if (!active || !task || kindOfGoal(task.goal) !== 'info') return false;
    this.complete(active, task, 'done');
    this.publish();
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
    this.lastActivity = this.log.now();
    this.startOptional(active, taskId);
    this.append({ type: 'quiz.answered', level: active.level.id, task: taskId, ...prediction, correct });
    this.complete(active, task, 'done', correct);
    this.publish();
    return { correct };
  }

  /** After observing, a learner whose prediction was wrong says what they see now. */
  reflect(taskId: string, prediction: Prediction): { correct: boolean } | undefined {
    const active = this.active;
    const task = active?.level.tasks.find((candidate) => candidate.id === taskId);
    const goal = task && predictionOf(task.goal);
    if (!active || !task || !goal || this.stageOf(active, task) !== 'reflect' || !fitsGoal(goal, prediction)) return undefined;
    const correct = isRightPrediction(goal, prediction);
    this.lastActivity = this.log.now();
    active.reveal = { quiz: taskId, reflection: prediction };
    this.append({ type: 'quiz.reflected', level: active.level.id, task: taskId, ...prediction, correct });
    this.publish();
    return { correct };
  }

  /** The learner has read a revealed prediction's explanation and moves on to the next task. */
  continueAfterReveal(taskId: string): boolean {
    const active = this.active;
    const task = active?.level.tasks.find((candidate) => candidate.id === taskId);
    if (!active || !task || this.stageOf(active, task) !== 'explain') return false;
    this.lastActivity = this.log.now();
    active.reveal = null;
    this.append({ type: 'quiz.explained', level: active.level.id, task: taskId });
    if (!active.current) this.showCurrentTask(active);
    this.publish();
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
    this.publish();
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
    this.publish();
    return shown;
  }

  /** Leaves out a task that is not required (no points). */
  skip(taskId: string): boolean {
    const found = this.workableTask(taskId);
    if (!found || found.active.required.has(taskId)) return false;
    this.startOptional(found.active, taskId);
    this.complete(found.active, found.task, 'skipped');
    this.publish();
    return true;
  }

  /** "Explain more" was opened, for a task or the level's intro. */
  expandExplanation(taskId: string | 'intro'): void {
    const active = this.active;
    if (!active || (taskId !== 'intro' && !active.level.tasks.some((task) => task.id === taskId))) return;
    this.lastActivity = this.log.now();
    if (taskId !== 'intro') this.startOptional(active, taskId);
    this.append({ type: 'explanation.expanded', level: active.level.id, task: taskId === 'intro' ? null : taskId });
    this.publish();
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
    if (this.log.now() - this.lastActivity < this.idleHintMs) return;
    const step = nextHintStep(task, NO_HINTS);
    if (step !== 'text' && step !== 'guidance') return;
    active.offered.add(task.id);
    this.append({ type: 'hint.offered', level: active.level.id, task: task.id, step });
    this.publish();
  }

  /** The tab was hidden or shown (document.visibilitychange, pagehide): active time leaves out hidden time. */
  visibilityChanged(visible: boolean): void {
    if (visible === this.visible) return;
    this.visible = visible;
    this.append({ type: visible ? 'tab.visible' : 'tab.hidden' });
    // Time away is not time stuck on the task.
    if (visible) this.lastActivity = this.log.now();
    this.publish();
  }

  // ─── Other progress ────────────────────────────────────────────────────────

  saveSandbox(scene: Scene): void {
    this.sandbox = scene;
    this.changed = true;
    this.award({ kind: 'sandbox-saved' });
    this.publish();
  }

  changeSettings(changes: Partial<QuestSettings>): void {
    this.settings = { ...this.settings, ...changes };
    this.changed = true;
    this.publish();
  }

  /**
   * Takes in what another tab saved (progress-merge.ts): its events, tasks, badges and hint
   * counts join ours, and its settings replace ours (the learner changed them there last).
   * The open level moves on when its current task was completed there. Returns false, and
   * tells no one, when there was nothing new; progress of a later epoch (a reset or import
   * there) is not merged: the caller replaces the engine.
   */
  absorb(theirs: Progress): boolean {
    const ours = this.progress;
    if ((theirs.epoch ?? '') !== (ours.epoch ?? '')) return false;
    if (holdsAll(ours, theirs) && JSON.stringify(theirs.settings) === JSON.stringify(ours.settings)) return false;
    const merged = mergeProgress(ours, theirs);
    this.levelProgress = reconcileLevels(merged.levels, this.levels);
    this.earned = merged.badges;
    this.settings = theirs.settings;
    this.log.adopt(merged.log);
    const active = this.active;
    if (active) {
      for (const taskId of [...active.tallies.keys()]) if (isCompleted(this.levelProgress[active.level.id], taskId)) active.tallies.delete(taskId);
      if (active.current && isCompleted(this.levelProgress[active.level.id], active.current.id)) this.showCurrentTask(active);
    }
    this.changed = true;
    this.publish();
    return true;
  }

  // ─── Rules ─────────────────────────────────────────────────────────────────

  /** The task if the learner can work on it now: in the open level, not done, and either current or not required. */
  private workableTask(taskId: string): { active: ActiveLevel; task: Task } | undefined {
    const active = this.active;
    const task = active?.level.tasks.find((candidate) => candidate.id === taskId);
    if (!active || !task || isCompleted(this.levelProgress[active.level.id], taskId)) return undefined;
    if (active.required.has(taskId) && active.current?.id !== taskId) return undefined;
    return { active, task };
  }

  /** Makes the first required task not yet done the current one, and completes it at once if its goal already holds. */
  private showCurrentTask(active: ActiveLevel): void {
    const { level } = active;
    const task = currentTask(level, this.levelProgress[level.id], active.required);
    active.current = task;
    if (!task) return;
    active.tallies.set(task.id, NO_EVENTS);
    this.lastActivity = this.log.now();
    this.append({ type: 'task.shown', level: level.id, task: task.id, mandatory: task.mandatory, required: true, kind: kindOfGoal(task.goal) });
    // A learner who already did what the task asks (say, set supersampling to 2 earlier) is not made to do it again.
    if (this.lastState && kindOfGoal(task.goal) === 'do' && checkGoal(task.goal, this.lastState, NO_EVENTS)) {
      this.complete(active, task, active.shownByApp.has(task.id) ? 'shown' : 'done');
    }
  }

  private complete(active: ActiveLevel, task: Task, how: HowCompleted, correct?: boolean, stars?: Stars): void {
    const { level, required } = active;
    const before = this.recordOf(level.id);
    const wasPassed = isPassed(level, before, required);
    const points = pointsFor(task, how, correct, stars);
    const scored = { ...(correct === undefined ? {} : { correct }), ...(stars === undefined ? {} : { stars }) };
    const record = { tasks: { ...before.tasks, [task.id]: { how, points, ...scored } }, hintsUsed: before.hintsUsed };
    this.levelProgress = { ...this.levelProgress, [level.id]: record };
    active.tallies.delete(task.id);
    if (active.ring?.task === task.id) active.ring = null;
    const isRequired = required.has(task.id);
    this.append({
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
      this.append({ type: 'level.passed', level: level.id });
      this.awardChapter(level.chapter);
    }
    for (const badge of levelBadgesEarned(level, record, required)) this.award(badge);
    const revealed = how === 'skipped' ? undefined : predictionRevealedBy(level, required, record, task);
    if (revealed) active.reveal = { quiz: revealed.id };
    // A revealed prediction holds the level: the next task comes when the learner continues.
    if (active.current?.id === task.id) {
      if (revealed) active.current = undefined;
      else this.showCurrentTask(active);
    }
  }

  private observerOf(active: ActiveLevel, quiz: Task): Task | undefined {
    return observerOf(active.level, active.required, quiz);
  }

  private stageOf(active: ActiveLevel, task: Task): PredictionStage {
    return stageOf(active.level, active.required, this.levelProgress[active.level.id], active.reveal, task);
  }

  private predictionIn(levelId: string, taskId: string): Prediction | undefined {
    return lastPrediction(this.log.events, levelId, taskId);
  }

  private predictionView(active: ActiveLevel, task: Task): PredictionView | undefined {
    const goal = predictionOf(task.goal);
    if (!goal) return undefined;
    const seed = `${this.log.data.startedAt}/${active.level.id}/${task.id}`;
    const prediction = this.predictionIn(active.level.id, task.id);
    const reflection = active.reveal?.quiz === task.id ? active.reveal.reflection : undefined;
    const observer = this.observerOf(active, task);
    const pictures = goal.kind === 'picture' ? this.picturesOf(active.level, goal) : undefined;
    return {
      ...(pictures ? { pictures } : {}),
      stage: this.stageOf(active, task),
      order: choiceOrder(predictionParts(goal).choices, seed),
      ...(prediction ? { prediction } : {}),
      ...(reflection ? { reflection } : {}),
      ...(observer ? { observer } : {}),
    };
  }

  /** A picture prediction's scenes, made once per level file (the UI caches their renders by scene). */
  private picturesOf(level: Level, goal: PictureGoal): readonly Scene[] {
    let scenes = this.pictureCache.get(goal);
    if (!scenes) this.pictureCache.set(goal, (scenes = pictureScenes(level.scene, goal)));
    return scenes;
  }

  /** For a task to do that checks a prediction still waiting for it: the quiz and the prediction. */
  private checksOf(active: ActiveLevel, task: Task): TaskView['checks'] {
    if (kindOfGoal(task.goal) !== 'do' || isCompleted(this.levelProgress[active.level.id], task.id)) return undefined;
    const quiz = active.level.tasks.find(
      (candidate) => predictionOf(candidate.goal) && this.stageOf(active, candidate) === 'wait' && this.observerOf(active, candidate) === task,
    );
    const prediction = quiz && this.predictionIn(active.level.id, quiz.id);
    const order = quiz && this.predictionView(active, quiz)?.order;
    return quiz && prediction && order ? { quiz, prediction, order } : undefined;
  }

  /**
   * Logs the learner's first move towards an optional task in this visit: its time runs
   * from here (spec/classroom.md), so a task nobody touched is not timed at all.
   */
  private startOptional(active: ActiveLevel, taskId: string): void {
    if (active.required.has(taskId) || active.started.has(taskId) || isCompleted(this.levelProgress[active.level.id], taskId)) return;
    active.started.add(taskId);
    this.append({ type: 'task.started', level: active.level.id, task: taskId });
  }

  /** A rung the learner opened: it counts against the level's "No hints needed" badge. */
  private hintShown(active: ActiveLevel, task: Task, step: HintStep, trigger: 'asked' | 'offered'): void {
    const { level } = active;
    const before = this.recordOf(level.id);
    this.levelProgress = { ...this.levelProgress, [level.id]: { ...before, hintsUsed: before.hintsUsed + 1 } };
    this.lastActivity = this.log.now();
    this.append({ type: 'hint.shown', level: level.id, task: task.id, step, trigger });
  }

  private recordOf(levelId: string): LevelProgress {
    return this.levelProgress[levelId] ?? { tasks: {}, hintsUsed: 0 };
  }

  private awardChapter(chapterId: string): void {
    const chapter = this.catalog.chapters.find((candidate) => candidate.id === chapterId);
    const levels = chapter?.entries.flatMap((entry) => (entry.ok ? [entry.level] : [])) ?? [];
    if (levels.every((level) => isPassed(level, this.levelProgress[level.id], requiredTaskIds(level, this.assignment)))) {
      this.award({ kind: 'chapter-done', chapter: chapterId });
    }
  }

  private award(badge: Badge): void {
    if (this.earned.some((earned) => sameBadge(earned.badge, badge))) return;
    const logged = this.append({ type: 'badge.earned', badge });
    this.earned = [...this.earned, { badge, t: logged.t }];
  }

  private taskView(active: ActiveLevel, task: Task): TaskView {
    const done = this.levelProgress[active.level.id]?.tasks[task.id];
    const required = active.required.has(task.id);
    const status: TaskStatus = done ? done.how : active.current?.id === task.id ? 'current' : required ? 'waiting' : 'open';
    const hints = active.hints.get(task.id) ?? NO_HINTS;
    const prediction = this.predictionView(active, task);
    const checks = this.checksOf(active, task);
    return {
      task,
      kind: kindOfGoal(task.goal),
      required,
      status,
      // A prediction's points show once its result has been observed (see `points`).
      points: prediction?.stage === 'wait' ? 0 : (done?.points ?? 0),
      ...(done?.correct === undefined ? {} : { correct: done.correct }),
      ...(done?.stars === undefined ? {} : { stars: done.stars }),
      ...(prediction ? { prediction } : {}),
      ...(checks ? { checks } : {}),
      hints: task.hints.slice(0, hints.texts),
      nextHint: done ? null : nextHintStep(task, hints),
      hintOffered: !done && active.offered.has(task.id),
    };
  }

  private append(event: QuestEvent): LoggedEvent {
    const logged = this.log.append(event);
    this.unpublished.push(logged);
    return logged;
  }

  /** Tells listeners once per call from outside, with everything that call logged. */
  private publish(): void {
    if (this.unpublished.length === 0 && !this.changed) return;
    const events = this.unpublished;
    this.unpublished = [];
    this.changed = false;
    for (const listener of [...this.listeners]) listener(events);
  }
}

/** A comparison as logged: with the counts, and the open level's challenge task and the match score its learner read. */
function comparisonEvent(active: ActiveLevel | null, action: Extract<LabAction, { type: 'challenge.compared' }>): QuestEvent {
  const { difference, renders, changes, rays } = action;
  const event = { type: 'challenge.compared' as const, level: active?.level.id ?? null, difference, renders, changes, rays };
  const task = active?.level.tasks.find((candidate) => active.tallies.has(candidate.id) && candidate.goal.kind === 'challenge');
  if (task?.goal.kind !== 'challenge') return event;
  return { ...event, task: task.id, score: matchScore(difference, task.goal.challenge.measure.threshold) };
}
