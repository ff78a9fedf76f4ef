import { describe, expect, it } from 'vitest';
import { failedRun, SandboxNotLoaded } from '../../../../src/ui/game/code-lab/lab-sandbox.ts';
import { sandboxUnavailableText } from '../../../../src/ui/game/code-lab/code-lab-texts.ts';

describe('a run that threw before it had an answer', () => {
  it('is "not run" when the sandbox page never loaded, not a failure of the learner’s code', () => {
    expect(failedRun(new SandboxNotLoaded('the code lab sandbox did not load'))).toEqual({ kind: 'unavailable' });
    expect(sandboxUnavailableText()).toMatch(/^Your code was not run/);
    expect(sandboxUnavailableText()).not.toMatch(/\.\.$/);
  });

  it('is a failure with its message for anything else', () => {
    expect(failedRun(new Error('boom'))).toEqual({ kind: 'failed', message: 'Error: boom', line: null });
  });
});
