import { msg, str } from '@lit/localize';
import type { LabAction } from '../lab-state/lab-action.ts';
import type { LabState, Selection } from '../lab-state/lab-state.ts';
import { gizmoModesFor } from './gizmo-modes.ts';
import type { ViewCommand } from './view-commands.ts';

/** What a view command asks of the store: an action to dispatch, and/or a note for the learner. */
export interface StateCommand {
  action?: LabAction;
  message?: string;
  /** What a key did, for the learner who cannot see it happen (the chosen pixel). */
  note?: string;
}

/**
 * The part of a view command that changes the lab state rather than the camera: the gizmo's
 * mode and options, deleting, deselecting (Escape), stepping through the selection (N) and
 * choosing a pixel of the camera's screen with keys (P, arrows).
 * Pure, so a key, a toolbar button and a test all get the same answer; null for the
 * commands that only move the view (orbit, pan, zoom, fly, help).
 */
export function stateCommand(command: ViewCommand, state: LabState): StateCommand | null {
  switch (command.kind) {
    case 'gizmo-mode': {
      const refused = state.selection !== null && !gizmoModesFor(state.selection, state.scene).includes(command.mode);
      return {
        action: { type: 'gizmo.changed', changes: { mode: command.mode } },
        ...(refused ? { message: msg('The selection cannot be changed that way, so its gizmo moves it instead.') } : {}),
      };
    }
    case 'toggle-space':
      return { action: { type: 'gizmo.changed', changes: { space: state.gizmo.space === 'local' ? 'world' : 'local' } } };
    case 'toggle-snap':
      return { action: { type: 'gizmo.changed', changes: { snap: !state.gizmo.snap } } };
    case 'delete':
      return deleteSelection(state.selection);
    case 'escape':
      if (state.selection) return { action: { type: 'selection.changed', selection: null } };
      return state.selectedPixel ? { action: { type: 'pixel.deselected' } } : {};
    case 'toggle-pixel':
      return state.selectedPixel ? { action: { type: 'pixel.deselected' } } : choosePixel(0, 0);
    case 'pixel-step': {
      const [columns, rows] = state.scene.camera.pixels;
      const [x, y] = state.selectedPixel ?? [0, 0];
      const next = [Math.min(columns - 1, Math.max(0, x + command.dx)), Math.min(rows - 1, Math.max(0, y + command.dy))] as const;
      return next[0] === x && next[1] === y ? {} : choosePixel(...next);
    }
    case 'select-next':
      return { action: { type: 'selection.changed', selection: nextSelection(state, command.step) } };
    default:
      return null;
  }
}

/** Pixel (x, y) of the camera's screen chosen: only its rays are shown (0, 0 is the top left). */
function choosePixel(x: number, y: number): StateCommand {
  return {
    action: { type: 'pixel.selected', pixel: [x, y] },
    note: msg(str`Pixel ${x}, ${y}: only its rays are shown. Arrow keys: the next pixel; Esc: every pixel.`),
  };
}

function deleteSelection(selection: Selection): StateCommand {
  if (selection?.kind === 'object') return { action: { type: 'object.deleted', id: selection.id } };
  if (selection?.kind === 'light') return { action: { type: 'light.deleted', id: selection.id } };
  if (selection?.kind === 'camera') return { message: msg("The ray tracer's camera cannot be deleted.") };
  return { message: msg('Select an object or a light first, then press Delete.') };
}

/** Steps through everything selectable: objects, then lights, then the camera (round). */
export function nextSelection({ scene, selection }: Pick<LabState, 'scene' | 'selection'>, step: 1 | -1): Exclude<Selection, null> {
  const all: Exclude<Selection, null>[] = [
    ...scene.objects.map((o) => ({ kind: 'object' as const, id: o.id })),
    ...scene.lights.map((l) => ({ kind: 'light' as const, id: l.id })),
    { kind: 'camera' as const },
  ];
  const index = all.findIndex((item) => sameSelection(selection, item));
  const next = index < 0 ? (step > 0 ? 0 : all.length - 1) : (index + step + all.length) % all.length;
  return all[next]!;
}

export function sameSelection(a: Selection, b: Selection): boolean {
  if (a === null || b === null) return a === b;
  if (a.kind === 'camera' || b.kind === 'camera') return a.kind === b.kind;
  return a.kind === b.kind && a.id === b.id;
}
