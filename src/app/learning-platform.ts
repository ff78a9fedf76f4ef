import { findLmsApi, type LmsConnection } from '../classroom/scorm/lms-api.ts';
import type { QuestSession } from './quest-session.ts';

/**
 * The game's session inside a school's learning platform (a SCORM package's launch: the
 * platform's API on a window above this one, docs/classroom.md). Only then is the bridge
 * (lms-bridge.ts) loaded: outside a platform this costs one search up the frames and
 * nothing changes. The platform's session is opened once per page; every game session
 * (a reset starts a new one) is followed until the returned function is called.
 */

let platform: Promise<{ follow(session: QuestSession): () => void } | null> | null = null;

function connect(window: Window): Promise<{ follow(session: QuestSession): () => void } | null> {
  const lms: LmsConnection | null = findLmsApi(window);
  if (!lms) return Promise.resolve(null);
  return import('./lms-bridge.ts').then(({ startLmsBridge }) => startLmsBridge(lms, window));
}

export function followInLearningPlatform(session: QuestSession, window: Window): () => void {
  platform ??= connect(window);
  let stop: (() => void) | null = null;
  let stopped = false;
  void platform.then((bridge) => {
    if (bridge && !stopped) stop = bridge.follow(session);
  });
  return () => {
    stopped = true;
    stop?.();
  };
}
