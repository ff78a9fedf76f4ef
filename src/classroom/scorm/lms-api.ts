/**
 * The learning platform's side of a SCORM launch: the API object the platform puts on a
 * window above the game's frame, and the standard search for it.
 *
 * SCORM 1.2 (ADL, SCORM Run-Time Environment 1.2, §3.3.6.1) calls it `API` and its methods
 * `LMSInitialize`, `LMSGetValue`…; SCORM 2004 4th edition (RTE 4th ed., §3.1.3) calls it
 * `API_1484_11` and its methods `Initialize`, `GetValue`…. The search walks up the frames'
 * parents and then the opener's, as ADL's reference script does, a bounded number of steps
 * (a cross-origin window throws on reading it: that is the end of that path). Both are
 * wrapped in one interface so that the rest of the bridge speaks one language.
 */

export type ScormVersion = '1.2' | '2004';

/** SCORM 1.2's API object (only what the game calls). */
export interface Scorm12Api {
  LMSInitialize(parameter: ''): string;
  LMSFinish(parameter: ''): string;
  LMSGetValue(element: string): string;
  LMSSetValue(element: string, value: string): string;
  LMSCommit(parameter: ''): string;
  LMSGetLastError(): string | number;
}

/** SCORM 2004's API object (only what the game calls). */
export interface Scorm2004Api {
  Initialize(parameter: ''): string;
  Terminate(parameter: ''): string;
  GetValue(element: string): string;
  SetValue(element: string, value: string): string;
  Commit(parameter: ''): string;
  GetLastError(): string | number;
}

/** Either version, with the same five calls. `set` returns whether the platform took the value. */
export interface LmsConnection {
  readonly version: ScormVersion;
  initialize(): boolean;
  get(element: string): string;
  set(element: string, value: string): boolean;
  commit(): boolean;
  terminate(): boolean;
  /** The platform's last error code ('0': none), for the console when a value is refused. */
  lastError(): string;
}

/** How far the search climbs: ADL's reference script gives up after 7 parents; 10 covers every platform's nesting we know of. */
const MAX_STEPS = 10;

type Searchable = { parent: Searchable | null; opener?: Searchable | null; API?: unknown; API_1484_11?: unknown };

/** The API the nearest window holds, 2004 first (a platform that offers both prefers it), or null. */
function apiOn(window: Searchable): LmsConnection | null {
  try {
    if (isApi(window.API_1484_11, 'Initialize')) return wrap2004(window.API_1484_11 as Scorm2004Api);
    if (isApi(window.API, 'LMSInitialize')) return wrap12(window.API as Scorm12Api);
  } catch {
    // Another origin's window: it cannot be read, so it holds no API for us.
  }
  return null;
}

function isApi(value: unknown, method: string): boolean {
  return typeof value === 'object' && value !== null && typeof (value as Record<string, unknown>)[method] === 'function';
}

/** Walks up from `start` (the game's own window is not searched: it never holds the platform's API). */
function climb(start: Searchable): LmsConnection | null {
  let window: Searchable | null = start;
  for (let step = 0; step < MAX_STEPS && window; step++) {
    let parent: Searchable | null;
    try {
      parent = window.parent;
    } catch {
      return null;
    }
    if (!parent || parent === window) return null;
    const found = apiOn(parent);
    if (found) return found;
    window = parent;
  }
  return null;
}

/** The platform's API above `window` (its parents, then its opener's), or null outside a SCORM launch. */
export function findLmsApi(window: Searchable): LmsConnection | null {
  const above = climb(window);
  if (above) return above;
  let opener: Searchable | null | undefined;
  try {
    opener = window.opener;
  } catch {
    return null;
  }
  return opener ? (apiOn(opener) ?? climb(opener)) : null;
}

/** SCORM returns the strings "true" and "false". */
const ok = (result: unknown) => String(result) === 'true';

function wrap12(api: Scorm12Api): LmsConnection {
  return {
    version: '1.2',
    initialize: () => ok(api.LMSInitialize('')),
    get: (element) => String(api.LMSGetValue(element) ?? ''),
    set: (element, value) => ok(api.LMSSetValue(element, value)),
    commit: () => ok(api.LMSCommit('')),
    terminate: () => ok(api.LMSFinish('')),
    lastError: () => String(api.LMSGetLastError()),
  };
}

function wrap2004(api: Scorm2004Api): LmsConnection {
  return {
    version: '2004',
    initialize: () => ok(api.Initialize('')),
    get: (element) => String(api.GetValue(element) ?? ''),
    set: (element, value) => ok(api.SetValue(element, value)),
    commit: () => ok(api.Commit('')),
    terminate: () => ok(api.Terminate('')),
    lastError: () => String(api.GetLastError()),
  };
}
