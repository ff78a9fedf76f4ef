import type { Store } from '../../lab-state/store.ts';
import type { CodeLabHost } from '../game/code-lab/code-lab-host.ts';

/** The lab's side of a code lab: each graded run goes to the store as code.graded, where the quest engine checks the goal. */
export function codeLabReporter(store: () => Store): CodeLabHost {
  return {
    graded: ({ lab, passed, total, failed }) => store().dispatch({ type: 'code.graded', lab, passed, total, failed }),
  };
}
