import type { Store } from '../../lab-state/store.ts';
import type { Scene } from '../../scene/scene.ts';
import type { LabView } from '../../view/lab-view.ts';
import type { CodeLabHost } from '../game/code-lab/code-lab-host.ts';

/**
 * The lab's side of a code lab: each graded run goes to the store as code.graded, where the
 * quest engine checks the goal; a failing case is drawn in the lab's 3D view (when it has one);
 * the level's scene is the one a render with the learner's function draws.
 */
export function codeLabReporter(store: () => Store, view: () => Pick<LabView, 'labCase'> | null, levelScene: () => Scene | undefined): CodeLabHost {
  return {
    levelScene: () => levelScene() ?? null,
    graded: ({ lab, passed, total, failed }) => store().dispatch({ type: 'code.graded', lab, passed, total, failed }),
    showCase: (drawing) => view()?.labCase.show(drawing),
  };
}
