import type { QuestClock } from '../quest/event-log.ts';
import type { Scene } from '../scene/scene.ts';

/** A scene being dragged is saved once it has rested this long (a drag is many changes). */
const REST_MS = 1000;
/** A settled edit is saved at once, but not more often than this (a held key is many edits). */
const GAP_MS = 200;

/**
 * Saves the free lab's scene when an edit ends: at once for a settled edit (at most one
 * save per GAP_MS, the rest at the end of that gap), after REST_MS of rest for a value still
 * being dragged (the store marks those `live`). `flush` saves what waits, for leaving the
 * free lab or the page. Only a changed scene is saved: orbiting the view or choosing an
 * object is no edit, and a scene loaded into the free lab (the sandbox, a shared scene) is
 * the one edits are measured against (`loaded`).
 */
export class SandboxSaver {
  private timer: ReturnType<typeof setTimeout> | undefined;
  private pending: Scene | null = null;
  /** The scene last loaded, saved or waiting: an action that leaves it as it is was no edit. */
  private known: Scene | null = null;
  private lastSave = Number.NEGATIVE_INFINITY;

  constructor(
    private readonly clock: QuestClock,
    private readonly save: (scene: Scene) => void,
  ) {}

  /** A scene was loaded into the lab: not an edit, but what the next edits change. */
  loaded(scene: Scene): void {
    this.flush();
    this.known = scene;
  }

  /** The lab's scene after an action; saved (now or soon) when the action changed it. */
  keep(scene: Scene, live: boolean): void {
    if (scene === this.known) return;
    clearTimeout(this.timer);
    this.pending = this.known = scene;
    const wait = live ? REST_MS : Math.max(0, this.lastSave + GAP_MS - this.clock.monotonicMs());
    if (wait === 0) this.flush();
    else this.timer = setTimeout(() => this.flush(), wait);
  }

  flush(): void {
    clearTimeout(this.timer);
    const scene = this.pending;
    this.pending = null;
    if (!scene) return;
    this.lastSave = this.clock.monotonicMs();
    this.save(scene);
  }
}
