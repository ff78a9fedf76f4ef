import { describe, expect, it } from 'vitest';
import { findLmsApi } from '../../../src/classroom/scorm/lms-api.ts';

// The standard search for the platform's API: up the parents, then the opener, a bounded
// number of steps; a window of another origin (reading it throws) ends the path.

type FakeWindow = { parent: FakeWindow | null; opener?: FakeWindow | null; API?: unknown; API_1484_11?: unknown };

function top(extra: Partial<FakeWindow> = {}): FakeWindow {
  const window: FakeWindow = { parent: null, ...extra };
  window.parent = window;
  return window;
}

function child(parent: FakeWindow, depth = 1): FakeWindow {
  let window = parent;
  for (let step = 0; step < depth; step++) window = { parent: window };
  return window;
}

const calls: string[] = [];
const api2004 = {
  Initialize: () => 'true',
  Terminate: () => 'true',
  GetValue: (element: string) => `v:${element}`,
  SetValue: (element: string, value: string) => (calls.push(`${element}=${value}`), 'true'),
  Commit: () => 'true',
  GetLastError: () => 0,
};
const api12 = {
  LMSInitialize: () => 'true',
  LMSFinish: () => 'false',
  LMSGetValue: () => '',
  LMSSetValue: () => 'false',
  LMSCommit: () => 'true',
  LMSGetLastError: () => 405,
};

describe('finding the learning platform’s API', () => {
  it('finds SCORM 2004’s API_1484_11 a few frames up, and speaks to it', () => {
    const lms = findLmsApi(child(top({ API_1484_11: api2004 }), 3))!;
    expect(lms.version).toBe('2004');
    expect([lms.initialize(), lms.get('cmi.entry'), lms.set('cmi.location', 'x'), lms.commit(), lms.terminate()]).toEqual([
      true,
      'v:cmi.entry',
      true,
      true,
      true,
    ]);
    expect(calls).toEqual(['cmi.location=x']);
  });

  it('finds SCORM 1.2’s API, 2004 preferred where a window has both, and reads its refusals', () => {
    const lms = findLmsApi(child(top({ API: api12 })))!;
    expect(lms.version).toBe('1.2');
    expect([lms.set('cmi.core.exit', 'x'), lms.lastError(), lms.terminate()]).toEqual([false, '405', false]);
    expect(findLmsApi(child(top({ API: api12, API_1484_11: api2004 })))!.version).toBe('2004');
  });

  it('looks in the opener’s frames (a platform that opens the activity in a new window)', () => {
    const launcher = child(top({ API_1484_11: api2004 }));
    expect(findLmsApi({ ...top(), opener: launcher })?.version).toBe('2004');
  });

  it('finds nothing outside a platform, beyond its steps, or behind another origin', () => {
    expect(findLmsApi(top())).toBeNull();
    expect(findLmsApi(child(top({ API_1484_11: api2004 }), 11))).toBeNull();
    const foreign = {
      get parent(): FakeWindow {
        throw new DOMException('Blocked a frame', 'SecurityError');
      },
    } as FakeWindow;
    expect(findLmsApi(child(foreign))).toBeNull();
    // An object named API that is not one (another script's global) is not taken for it.
    expect(findLmsApi(child(top({ API: { version: 3 } })))).toBeNull();
  });
});
