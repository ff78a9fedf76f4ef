import type { LabState } from '../lab-state/lab-state.ts';
import type { Store } from '../lab-state/store.ts';
import type { QuestEngine } from '../quest/quest-engine.ts';

// The ray palette is the learner's setting, saved with the progress (the ray panel's switch
// and the menu both change it through the store): a colour-blind learner chooses it once.

/** The lab's palette, into the progress when the learner changed it. */
export function keepPalette(engine: QuestEngine, state: LabState): void {
  const colorBlindPalette = state.rays.colorBlindPalette;
  if (colorBlindPalette !== engine.progress.settings.colorBlindPalette) engine.changeSettings({ colorBlindPalette });
}

/** The saved palette, into the lab (at the start, after an import or a reset). */
export function applyPalette(engine: QuestEngine, store: Store): void {
  const colorBlindPalette = engine.progress.settings.colorBlindPalette;
  if (store.state.rays.colorBlindPalette !== colorBlindPalette) store.dispatch({ type: 'rays.changed', changes: { colorBlindPalette } });
}
