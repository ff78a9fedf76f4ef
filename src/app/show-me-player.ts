import type { DebuggerAction, LabAction } from '../lab-state/lab-action.ts';

/**
 * "Show me" (the hint ladder's last rung) performs a task's solution so the learner SEES it
 * done: a state change goes through the store like any panel edit, but a fact (the view
 * turned, a render finished) cannot be dispatched into being: the player makes it happen
 * through the real UI (the view orbits, the render window opens and renders), and the view
 * or the window then reports the fact as it always does.
 */

/** One visible step of a solution. */
export type ShowMeStep =
  | { kind: 'dispatch'; action: LabAction }
  | { kind: 'orbit' }
  | { kind: 'pan' }
  | { kind: 'zoom' }
  | { kind: 'fly-to-camera' }
  | { kind: 'open-render' }
  | { kind: 'render' }
  | { kind: 'open-panel'; panel: string }
  /** The ray debugger goes to the action's ray or clicks its term (and reports it). */
  | { kind: 'debug'; action: DebuggerAction };

/** Whether an action is a fact reported by the UI (performed through it) or a state change (dispatched). */
export function kindOfAction(action: LabAction): 'fact' | 'state' {
  switch (action.type) {
    case 'view.orbited':
    case 'view.panned':
    case 'view.zoomed':
    case 'view.flew-to-camera':
    case 'render.started':
    case 'render.finished':
    case 'render.cancelled':
    case 'render.saved':
    case 'scene.saved':
    case 'panel.opened':
    case 'debugger.stepped':
    case 'debugger.term-clicked':
      return 'fact';
    default:
      return 'state';
  }
}

/**
 * The steps that perform `actions`. A render's facts (started, then finished) are one step,
 * a real render, whose window reports both; a cancel or a save (of an image or a scene)
 * cannot be shown honestly (nothing to cancel, a file dialog) and is passed over.
 */
export function showMeSteps(actions: readonly LabAction[]): ShowMeStep[] {
  const steps: ShowMeStep[] = [];
  const last = () => steps[steps.length - 1];
  for (const action of actions) {
    switch (action.type) {
      case 'view.orbited':
        steps.push({ kind: 'orbit' });
        break;
      case 'view.panned':
        steps.push({ kind: 'pan' });
        break;
      case 'view.zoomed':
        steps.push({ kind: 'zoom' });
        break;
      case 'view.flew-to-camera':
        steps.push({ kind: 'fly-to-camera' });
        break;
      case 'render.started':
      case 'render.finished':
        if (last()?.kind !== 'render') steps.push({ kind: 'render' });
        break;
      case 'render.cancelled':
      case 'render.saved':
      case 'scene.saved':
        break;
      case 'panel.opened':
        steps.push(action.panel === 'render' ? { kind: 'open-render' } : { kind: 'open-panel', panel: action.panel });
        break;
      case 'debugger.stepped':
      case 'debugger.term-clicked':
        steps.push({ kind: 'debug', action });
        break;
      default:
        steps.push({ kind: 'dispatch', action });
    }
  }
  return steps;
}

/** What the player needs of the lab to perform a step; each returns when the step is under way. */
export interface ShowMeStage {
  dispatch(action: LabAction): void;
  orbit(): void;
  pan(): void;
  zoom(): void;
  flyToCamera(): void;
  openRender(): void;
  /** Opens the render window and starts a real render. */
  render(): void;
  openPanel(panel: string): void;
  /** Has the ray debugger perform the action (open on the selected pixel, go to the ray or click the term). */
  debug(action: DebuggerAction): void;
}

/** Time between steps: long enough to see each one happen, short enough not to bore. */
export const SHOW_ME_STEP_MS = 600;

/**
 * Performs `steps` one after another, `stepMs` apart. Returns a function that stops the
 * rest (the learner closed the level, or asked again).
 */
export function playShowMe(steps: readonly ShowMeStep[], stage: ShowMeStage, stepMs = SHOW_ME_STEP_MS, onDone?: () => void): () => void {
  let index = 0;
  let timer: ReturnType<typeof setTimeout> | undefined;
  const perform = () => {
    const step = steps[index++];
    if (!step) {
      onDone?.();
      return;
    }
    performStep(step, stage);
    timer = setTimeout(perform, stepMs);
  };
  // The first step waits too: the learner's eyes go from the button to the scene first.
  timer = setTimeout(perform, stepMs);
  return () => clearTimeout(timer);
}

function performStep(step: ShowMeStep, stage: ShowMeStage): void {
  switch (step.kind) {
    case 'dispatch':
      return stage.dispatch(step.action);
    case 'orbit':
      return stage.orbit();
    case 'pan':
      return stage.pan();
    case 'zoom':
      return stage.zoom();
    case 'fly-to-camera':
      return stage.flyToCamera();
    case 'open-render':
      return stage.openRender();
    case 'render':
      return stage.render();
    case 'open-panel':
      return stage.openPanel(step.panel);
    case 'debug':
      return stage.debug(step.action);
  }
}
