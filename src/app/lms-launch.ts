import { findLmsApi } from '../classroom/scorm/lms-api.ts';

/**
 * Whether the game runs inside a school's learning platform (a SCORM package's launch: the
 * platform's API on a window above this one). Only then is the bridge loaded: outside a
 * platform this costs one search up the frames and nothing changes. Called from main.ts
 * before the game starts, so that progress the platform kept is in place when it does.
 */
export async function joinLearningPlatform(window: Window): Promise<void> {
  const lms = findLmsApi(window);
  if (!lms) return;
  const { startLmsBridge } = await import('./lms-bridge.ts');
  await startLmsBridge(lms, window);
}
