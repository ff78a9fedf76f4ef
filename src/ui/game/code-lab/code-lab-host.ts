import { createContext } from '@lit/context';

import type { CaseDrawing } from '../../../quest/code-labs/case-drawing.ts';
import type { Scene } from '../../../scene/scene.ts';

/**
 * What the code lab panel asks of the lab: to report a graded run (the quest engine checks the
 * goal with it), to draw a failing case in the 3D view (null: none), and the level's scene, to
 * render with the learner's function (null: no level is open).
 */
export interface CodeLabHost {
  graded(run: { lab: string; passed: number; total: number; failed: string | null }): void;
  showCase(drawing: CaseDrawing | null): void;
  levelScene(): Scene | null;
}

export const codeLabHostContext = createContext<CodeLabHost | undefined>(Symbol('code-lab-host'));
