import { ALWAYS_SHOWN, UI_PANELS, type LabPanel } from '../../quest/lab-controls.ts';
import type { Level } from '../../quest/level-schema.ts';
import type { MovableItems } from '../../quest/movable-items.ts';

/** What of the lab a level shows: its panels, and the controls it narrows each one to. */
export interface LevelPanels {
  panels: ReadonlySet<LabPanel>;
  /** The level's `ui.controls` for a panel (undefined: all of that panel's controls). */
  controls(panel: LabPanel): readonly string[] | undefined;
  /** The gizmo buttons on show: none without the gizmo panel, else the level's choice (undefined: all). */
  gizmo: readonly string[] | undefined;
  /** The only scene items the gizmo may change (the level's ui.movable; undefined: all). */
  movable: MovableItems;
  /**
   * Whether the ray colours' legend goes over the 3D view: where the level's ray panel does
   * not show it, which rays are which must still be readable wherever rays are drawn.
   */
  viewLegend: boolean;
}

/** A level's own choice of panels and controls (plus the view and its screen), or everything in the free lab. */
export function levelPanels(level: Level | undefined): LevelPanels {
  if (!level)
    return { panels: new Set<LabPanel>([...ALWAYS_SHOWN, ...UI_PANELS]), controls: () => undefined, gizmo: undefined, movable: undefined, viewLegend: false };
  const panels = new Set<LabPanel>([...ALWAYS_SHOWN, ...level.ui.panels]);
  const chosen = level.ui.controls as Partial<Record<LabPanel, readonly string[]>> | undefined;
  const panelLegend = panels.has('rays') && (chosen?.rays?.includes('legend') ?? true);
  return {
    panels,
    controls: (panel) => chosen?.[panel],
    gizmo: panels.has('gizmo') ? chosen?.gizmo : [],
    movable: level.ui.movable,
    viewLegend: !panelLegend,
  };
}
