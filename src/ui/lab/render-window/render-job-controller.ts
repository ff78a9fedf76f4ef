import type { ReactiveController, ReactiveControllerHost } from 'lit';
import { loadMeshes } from '../../../render/load-meshes-browser.ts';
import type { PathCount, RenderChanges, RenderImage, RenderJob, RenderProgress } from '../../../render/render-job.ts';
import { RenderWorkersUnavailable, type RenderPool } from '../../../render/render-pool.ts';
import type { Store } from '../../../lab-state/store.ts';
import { meshNamesInScene } from '../../../scene/mesh-names.ts';
import type { Scene } from '../../../scene/scene.ts';
import type { Quantization } from '../../../tracer/quantize.ts';
import { PartialPicture } from './partial-picture.ts';
import { countRays } from './render-figures.ts';

/** Where the render on show is in its life. */
export type RenderStatus =
  | { kind: 'idle' }
  /** Models loading and the job starting, before the first progress. */
  | { kind: 'starting' }
  | ({ kind: 'rendering' } & RenderProgress)
  | { kind: 'finished'; ms: number; rays: number; workers: number }
  /** byUser: the Cancel button; otherwise the pool dropped the job (a new scene or render). `paths`: a path render's count on show. */
  | { kind: 'cancelled'; byUser: boolean; paths?: PathCount | null }
  /** `unloadable`: the workers' code could not be loaded (render-pool.ts): only a reload helps. */
  | { kind: 'failed'; message: string; unloadable: boolean };

/** The render on show: what was rendered, and from which of the store's scene revisions. */
export interface ShownRender {
  scene: Scene;
  revision: number;
  width: number;
  height: number;
}

/** What the window does with a render's pictures while the job runs. */
export interface RenderPainter {
  /** The finished image, all of it. */
  paint(image: RenderImage, quantization: Quantization): void;
  /** A running job's changes (new preview rows, tiles of its full-resolution `image`). */
  paintChanges(image: RenderImage, changes: RenderChanges, quantization: Quantization): void;
  /** A render starts (after `shown` is set, before any picture): `isCurrent` says whether it still is. */
  started(shown: ShownRender, isCurrent: () => boolean): Promise<void> | void;
}

/**
 * The render window's job as a state machine: idle → starting → rendering → finished,
 * cancelled or failed. One render at a time; a newer render or a cancel drops the older
 * one, whose late answers are ignored by number. The store hears render.started,
 * render.finished {ms} and render.cancelled (the quest engine and the timing log listen).
 */
export class RenderJobController implements ReactiveController {
  status: RenderStatus = { kind: 'idle' };
  shown: ShownRender | null = null;
  /** The finished image, for Save as PNG. */
  finished: RenderImage | null = null;
  /** What the running (or cancelled) render has shown so far. */
  private readonly shownSoFar = new PartialPicture();
  /** A cancelled render's image, which no tile changes any more; null otherwise. */
  private cancelledImage: RenderImage | null = null;
  /** Each render's number; a late answer from an older one is ignored. */
  private renderId = 0;
  private job: RenderJob | null = null;

  constructor(
    private readonly host: ReactiveControllerHost,
    private readonly painter: RenderPainter,
  ) {
    host.addController(this);
  }

  get running(): boolean {
    return this.status.kind === 'starting' || this.status.kind === 'rendering';
  }

  /** Whether a cancelled render traced something that Save as PNG can save. */
  get hasPartial(): boolean {
    return this.status.kind === 'cancelled' && this.cancelledImage !== null && this.shownSoFar.traced;
  }

  /**
   * A cancelled render's picture as it was on show (traced tiles, the coarse preview elsewhere),
   * made when it is saved so that a big image is not copied for nothing; null when there is none.
   */
  partialPicture(): RenderImage | null {
    return this.hasPartial && this.cancelledImage ? this.shownSoFar.picture(this.cancelledImage) : null;
  }

  /** The scene changed since the render on show (by the store's revision, not by content). */
  isStale(store: Store | undefined): boolean {
    return this.shown !== null && store !== undefined && store.sceneRevision !== this.shown.revision;
  }

  hostDisconnected(): void {
    if (this.running) this.stop();
  }

  /** Renders the store's scene at its image size, replacing the render on show. */
  async start(store: Store, pool: RenderPool): Promise<void> {
    if (this.running) this.stop();
    const id = ++this.renderId;
    const isCurrent = () => id === this.renderId;
    const scene = store.state.scene;
    const [width, height] = scene.settings.imageSize;
    this.shown = { scene, revision: store.sceneRevision, width, height };
    this.finished = null;
    this.cancelledImage = null;
    this.shownSoFar.reset();
    this.setStatus({ kind: 'starting' });
    store.dispatch({ type: 'render.started' });
    await this.painter.started(this.shown, isCurrent);
    const quantization: Quantization = scene.settings;
    try {
      const meshes = await loadMeshes(meshNamesInScene(scene));
      if (!isCurrent()) return;
      // Progress comes after every pass's last tile too, so painting the changes there shows
      // each preview whole without repainting the image at every pass.
      const job = pool.render(scene, meshes, {
        onProgress: (progress) => {
          if (!isCurrent()) return;
          this.setStatus({ kind: 'rendering', ...progress });
          const changes = job.changes();
          if (!changes) return;
          this.shownSoFar.note(job.image, changes);
          this.painter.paintChanges(job.image, changes, quantization);
        },
      });
      this.job = job;
      const result = await job.done;
      if (!isCurrent()) return;
      this.job = null;
      if (result.cancelled) {
        this.cancelledImage = job.image;
        this.setStatus({ kind: 'cancelled', byUser: false });
        return;
      }
      this.finished = result;
      this.painter.paint(result, quantization);
      const rays = countRays(result.stats);
      this.setStatus({ kind: 'finished', ms: result.ms, rays, workers: result.workers });
      store.dispatch({ type: 'render.finished', ms: result.ms, rays });
    } catch (error) {
      if (!isCurrent()) return;
      this.job = null;
      this.setStatus({ kind: 'failed', message: errorMessage(error), unloadable: error instanceof RenderWorkersUnavailable });
    }
  }

  /** Stops the running render (its partial image stays on show). */
  cancel(store: Store | undefined): void {
    if (!this.running) return;
    this.cancelledImage = this.job?.image ?? null;
    const paths = this.status.kind === 'rendering' ? this.status.paths : null;
    this.stop();
    this.setStatus({ kind: 'cancelled', byUser: true, paths });
    store?.dispatch({ type: 'render.cancelled' });
  }

  /** Drops the current render: its late answers are ignored from now on. */
  private stop(): void {
    this.renderId++;
    this.job?.cancel();
    this.job = null;
  }

  private setStatus(status: RenderStatus): void {
    this.status = status;
    this.host.requestUpdate();
  }
}

export function errorMessage(error: unknown): string {
  return error instanceof Error ? error.message : String(error);
}
