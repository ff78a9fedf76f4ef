import { createContext } from '@lit/context';

/** What the code lab panel asks of the lab: to report a graded run (the quest engine checks the goal with it). */
export interface CodeLabHost {
  graded(run: { lab: string; passed: number; total: number; failed: string | null }): void;
}

export const codeLabHostContext = createContext<CodeLabHost | undefined>(Symbol('code-lab-host'));
