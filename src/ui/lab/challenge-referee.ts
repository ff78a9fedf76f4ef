import type { LabServices } from '../../app/lab-services.ts';
import type { Store } from '../../lab-state/store.ts';
import type { RenderImage } from '../../render/render-job.ts';
import { challengeScenes, meanLinearDifference, pixelDifferences, shownLight } from '../../quest/challenge-closeness.ts';
import type { ChallengeGoal } from '../../quest/goal.ts';
import type { Scene } from '../../scene/scene.ts';
import { toRgba8 } from '../../tracer/quantize.ts';
import type { ChallengePictures, ChallengeView } from '../game/challenge-pictures.ts';

const NOTHING_YET: ChallengeView = {
  target: null,
  attempt: null,
  difference: null,
  value: null,
  renders: 0,
  changes: 0,
  rays: 0,
  matched: null,
  measuring: false,
};

/**
 * The lab's referee of a match-the-target challenge. While a challenge panel watches a goal,
 * every finished render of the learner's (its rays counted) is rendered again at the challenge's small size on
 * the services' picture worker, with the target beside it (the same tracer and seed, so the
 * same scene gives the same picture), measured, and reported to the store as
 * challenge.compared with the counts so far: the quest engine checks the goal, logs each
 * comparison and keeps the stars of a match. Changes to
 * the scene are counted too; a loaded scene (the level opened again) starts the count anew.
 */
export class ChallengeReferee implements ChallengePictures {
  private goal: ChallengeGoal | null = null;
  private view: ChallengeView = NOTHING_YET;
  private readonly listeners = new Set<(view: ChallengeView) => void>();

  constructor(
    private readonly services: () => LabServices,
    private readonly levelScene: () => Scene | undefined,
  ) {}

  /** Follows the store; returns the function that stops. */
  attach(store: Store): () => void {
    let scene = store.state.scene;
    return store.subscribe((state, action, error, live) => {
      const changed = state.scene !== scene;
      scene = state.scene;
      if (error || live || !this.goal) return;
      if (action.type === 'scene.loaded') this.update({ ...NOTHING_YET, target: this.view.target });
      else if (action.type === 'render.finished') {
        this.update({ rays: this.view.rays + (action.rays ?? 0) });
        void this.measure(store, this.goal, state.scene);
      } else if (changed) this.update({ changes: this.view.changes + 1 });
    });
  }

  watch(goal: ChallengeGoal, listener: (view: ChallengeView) => void): () => void {
    if (goal !== this.goal) {
      this.goal = goal;
      this.view = NOTHING_YET;
      void this.drawTarget(goal);
    }
    this.listeners.add(listener);
    listener(this.view);
    return () => this.listeners.delete(listener);
  }

  private async drawTarget(goal: ChallengeGoal): Promise<void> {
    const scenes = this.scenesFor(goal, this.levelScene());
    if (!scenes) return;
    try {
      const target = await this.services().renderPicture(scenes.target);
      if (goal === this.goal) this.update({ target: picture(target, scenes.target) });
    } catch {
      // No worker (an old browser): the panel says to render, and the render window says why it cannot.
    }
  }

  private async measure(store: Store, goal: ChallengeGoal, scene: Scene): Promise<void> {
    const scenes = this.scenesFor(goal, scene);
    if (!scenes) return;
    this.update({ measuring: true });
    try {
      const [target, attempt] = await Promise.all([this.services().renderPicture(scenes.target), this.services().renderPicture(scenes.attempt)]);
      if (goal !== this.goal) return;
      const targetLight = shownLight(target.rgb, scenes.target.settings);
      const attemptLight = shownLight(attempt.rgb, scenes.attempt.settings);
      const value = meanLinearDifference(targetLight, attemptLight);
      const counts = { renders: this.view.renders + 1, changes: this.view.changes, rays: this.view.rays };
      const matched = value <= goal.challenge.measure.threshold;
      this.update({
        target: picture(target, scenes.target),
        attempt: picture(attempt, scenes.attempt),
        difference: differencePicture(targetLight, attemptLight, target.width, target.height),
        value,
        renders: counts.renders,
        matched: this.view.matched ?? (matched ? counts : null),
        measuring: false,
      });
      store.dispatch({ type: 'challenge.compared', difference: value, ...counts });
    } catch {
      this.update({ measuring: false });
    }
  }

  private scenesFor(goal: ChallengeGoal, learnerScene: Scene | undefined): { target: Scene; attempt: Scene } | null {
    const levelScene = this.levelScene();
    return levelScene && learnerScene ? challengeScenes(levelScene, goal, learnerScene) : null;
  }

  private update(changes: Partial<ChallengeView>): void {
    this.view = { ...this.view, ...changes };
    for (const listener of [...this.listeners]) listener(this.view);
  }
}

/** A render as the render window shows it (its encoding and dithering). */
function picture(image: RenderImage, scene: Scene): ImageData {
  const rgba = toRgba8(image.rgb, image.width, image.height, scene.settings) as Uint8ClampedArray<ArrayBuffer>;
  return new ImageData(rgba, image.width, image.height);
}

/** Grey where the two differ: the square root lifts small differences (0.01 shows as 10 % grey) so a near miss is still seen. */
function differencePicture(a: Float32Array, b: Float32Array, width: number, height: number): ImageData {
  const differences = pixelDifferences(a, b);
  const rgba = new Uint8ClampedArray(differences.length * 4);
  differences.forEach((difference, pixel) => {
    const grey = Math.round(Math.sqrt(difference) * 255);
    rgba.set([grey, grey, grey, 255], pixel * 4);
  });
  return new ImageData(rgba, width, height);
}
