import { describe, expect, it } from 'vitest';
import { codeRunEvent } from '../../src/quest/code-run-event.ts';
import type { Level } from '../../src/quest/level-schema.ts';

const level = {
  id: '02-rays-from-the-camera',
  tasks: [
    { id: 'look', goal: { kind: 'event' } },
    { id: 'code-hit-sphere', goal: { kind: 'code', code: { lab: 'ray-sphere' } } },
  ],
} as unknown as Level;
const action = { type: 'code.graded', lab: 'ray-sphere', passed: 250, total: 306, failed: 'sphere-behind' } as const;

describe('a code lab run as logged', () => {
  it('names the open level and its code task for the lab', () => {
    expect(codeRunEvent(level, action)).toEqual({
      type: 'code.graded',
      level: '02-rays-from-the-camera',
      task: 'code-hit-sphere',
      lab: 'ray-sphere',
      passed: 250,
      total: 306,
      failed: 'sphere-behind',
    });
  });

  it('has no task when no open level has a task for that lab', () => {
    expect(codeRunEvent(null, action)).toEqual({ type: 'code.graded', level: null, lab: 'ray-sphere', passed: 250, total: 306, failed: 'sphere-behind' });
    expect(codeRunEvent(level, { ...action, lab: 'mirror' })).not.toHaveProperty('task');
  });
});
