import type { Prediction } from '../../quest/goal-check.ts';

/**
 * What the task panel asks of the game, in one `quest-command` event (bubbling, composed)
 * that the lab hands to the quest session.
 */
export type QuestCommand =
  | { kind: 'next' }
  | { kind: 'predict'; task: string; prediction: Prediction }
  | { kind: 'reflect'; task: string; prediction: Prediction }
  | { kind: 'continue'; task: string }
  | { kind: 'hint'; task: string }
  | { kind: 'show-me'; task: string }
  | { kind: 'skip'; task: string }
  | { kind: 'explain'; task: string | 'intro' }
  | { kind: 'next-level' }
  | { kind: 'map' };

export const QUEST_COMMAND = 'quest-command';
