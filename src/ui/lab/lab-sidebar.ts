import { msg } from '@lit/localize';
import { html, nothing, type TemplateResult } from 'lit';
import type { LabState } from '../../lab-state/lab-state.ts';
import type { UiPanel } from '../../quest/lab-controls.ts';
import { ON_DEMAND_PANELS } from './lab-elements.ts';
import type { LevelPanels } from './level-panels.ts';

/**
 * The editing panels of the lab's left column that the level shows, in their order: the
 * scene list, the selected light's or object's panel, the tracer, the rays, the BVH (loaded
 * on demand: its message when it could not be) and the file panel.
 */
export function labSidebar(state: LabState, { panels, controls, movable }: Pick<LevelPanels, 'panels' | 'controls' | 'movable'>): TemplateResult[] {
  const shows = (panel: UiPanel) => panels.has(panel);
  const panel = (name: UiPanel, part: TemplateResult) => (shows(name) ? part : nothing);
  return [
    panel(
      'scene-list',
      html`<rt-scene-list .allowEditing=${shows('add-remove')} .shownControls=${controls('scene-list')} .movable=${movable}></rt-scene-list>`,
    ),
    state.selection?.kind === 'light' && shows('light')
      ? html`<rt-light-panel .shownControls=${controls('light')}></rt-light-panel>`
      : shows('object')
        ? html`<rt-object-panel .shownControls=${controls('object')}></rt-object-panel>`
        : panel('light', html`<rt-light-panel .shownControls=${controls('light')}></rt-light-panel>`),
    panel('tracer', html`<rt-tracer-panel .shownControls=${controls('tracer')}></rt-tracer-panel>`),
    panel('rays', html`<rt-ray-panel .shownControls=${controls('rays')}></rt-ray-panel>`),
    panel(
      'bvh',
      ON_DEMAND_PANELS.bvh?.state === 'failed'
        ? html`<rt-load-problem .text=${msg('This panel could not be loaded.')} .reason=${ON_DEMAND_PANELS.bvh.problem}></rt-load-problem>`
        : html`<rt-bvh-panel .shownControls=${controls('bvh')}></rt-bvh-panel>`,
    ),
    panel('file', html`<rt-file-panel></rt-file-panel>`),
  ].filter((part): part is TemplateResult => part !== nothing);
}
