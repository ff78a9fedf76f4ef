import { createContext } from '@lit/context';
import type { ChallengeCounts } from '../../quest/challenge-par.ts';
import type { ChallengeGoal } from '../../quest/goal.ts';

/** What the challenge panel shows: the latest comparison of the learner's render with the target. */
export interface ChallengeView {
  /** The target picture, as the render window would show it; null until rendered (or when it failed). */
  target: ImageData | null;
  /** The learner's last render at the challenge's size, and where it differs from the target (brighter: further off). */
  attempt: ImageData | null;
  difference: ImageData | null;
  /** The measure of the last comparison (challenge-closeness.ts); null before the first render. */
  value: number | null;
  /** Renders compared, changes to the scene, and rays the learner's renders traced, since the level opened. */
  renders: number;
  changes: number;
  rays: number;
  /** The counts when the render first came within the threshold (its golf score); null while not yet matched. */
  matched: ChallengeCounts | null;
  /** A comparison is being rendered. */
  measuring: boolean;
}

/**
 * The lab's referee of a challenge: it renders the target, measures each render of the
 * learner's (and reports it to the store as challenge.compared), and tells the panel.
 */
export interface ChallengePictures {
  /** The view for this goal now, and each time it changes; returns the function that stops it. */
  watch(goal: ChallengeGoal, listener: (view: ChallengeView) => void): () => void;
}

export const challengePicturesContext = createContext<ChallengePictures | undefined>(Symbol('challenge-pictures'));
