import { createContext } from '@lit/context';

import type { CaseDrawing } from '../../../quest/code-labs/case-drawing.ts';

/** What the code lab panel asks of the lab: to report a graded run (the quest engine checks the goal with it), and to draw a failing case in the 3D view (null: none). */
export interface CodeLabHost {
  graded(run: { lab: string; passed: number; total: number; failed: string | null }): void;
  showCase(drawing: CaseDrawing | null): void;
}

export const codeLabHostContext = createContext<CodeLabHost | undefined>(Symbol('code-lab-host'));
