import type { QuestSession } from './quest-session.ts';

/**
 * Features that follow the game's session without the session knowing of them (the
 * learning platform's bridge: lms-bridge.ts). A hook is told of every session the game
 * starts (a reset starts a new one) and returns how to stop following it.
 */
export type SessionHook = (session: QuestSession) => () => void;

const hooks = new Set<SessionHook>();

export function onQuestSession(hook: SessionHook): void {
  hooks.add(hook);
}

/** The game started `session` (quest-controller.ts): every hook follows it until the returned function is called. */
export function questSessionStarted(session: QuestSession): () => void {
  const stops = [...hooks].map((hook) => hook(session));
  return () => stops.forEach((stop) => stop());
}
