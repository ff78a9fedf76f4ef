import type { LabAction } from './lab-action.ts';
import { reduce, type Reduction } from './lab-reducer.ts';
import type { LabState } from './lab-state.ts';
import { wordedIssue, type Issue } from '../util/issue.ts';

/**
 * Called after every dispatched action with the state it produced (unchanged when refused).
 * `live` marks a value the learner is still dragging through: a settled action follows it.
 */
export type StoreListener = (state: LabState, action: LabAction, error?: Issue[], live?: boolean) => void;

/** How an action was dispatched. */
export interface DispatchOptions {
  /** A value passed while dragging (a slider's `input`), not the one the learner settles on. */
  live?: boolean;
}

/**
 * Holds the lab state and applies named actions to it (three.js editor's "every change is
 * a command with a name", without its untyped signals). Listeners: the view, the panels,
 * the quest engine and the timing log.
 */
export class Store {
  private current: LabState;
  private readonly listeners = new Set<StoreListener>();
  private revision = 0;

  constructor(initial: LabState) {
    this.current = initial;
  }

  get state(): LabState {
    return this.current;
  }

  /**
   * Counts the scene changes the store has accepted: equal numbers mean the same scene, so a
   * render can tell it is stale without comparing scenes (a change back still counts).
   */
  get sceneRevision(): number {
    return this.revision;
  }

  /** Applies the action; returns the reasons when it was refused (the state is then unchanged). */
  dispatch(action: LabAction, options: DispatchOptions = {}): Issue[] | undefined {
    const { state, error } = safeReduce(this.current, action);
    if (state.scene !== this.current.scene) this.revision++;
    this.current = state;
    for (const listener of [...this.listeners]) listener(state, action, error, options.live === true);
    return error;
  }

  /** Returns the function that unsubscribes. */
  subscribe(listener: StoreListener): () => void {
    this.listeners.add(listener);
    return () => this.listeners.delete(listener);
  }
}

/** A bug in a reducer must not take the app down: the change is refused with its reason. */
function safeReduce(state: LabState, action: LabAction): Reduction {
  try {
    return reduce(state, action);
  } catch (error) {
    // A bug, not a mistake of the learner's: said as the browser words it.
    return { state, error: [wordedIssue(action.type, error instanceof Error ? error.message : String(error))] };
  }
}
