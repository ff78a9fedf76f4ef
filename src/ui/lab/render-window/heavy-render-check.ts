import { msg, str } from '@lit/localize';
import { html, type ReactiveController, type ReactiveControllerHost } from 'lit';
import { loadMeshes } from '../../../render/load-meshes-browser.ts';
import { lighterRenders, type LighterRender, type RenderEstimate } from '../../../render/render-estimate.ts';
import type { RenderPool } from '../../../render/render-pool.ts';
import { estimateHere, mayBeLong } from '../../../render/render-probe.ts';
import { EstimateCalibration } from '../../../render/estimate-calibration.ts';
import { meshNamesInScene } from '../../../scene/mesh-names.ts';
import type { Scene } from '../../../scene/scene.ts';
import { formatCount, formatWait } from './render-figures.ts';

/** The machine is the same for every render of the page: one record of how its estimates came true. */
const sessionCalibration = new EstimateCalibration();

/** Whether a render may start, and the seconds a probe on this machine promised for it (null: not measured). */
export type StartDecision = { start: false } | { start: true; expectedSeconds: number | null };

/** A render estimated over a minute on this machine, waiting for the learner's choice. */
export interface HeavyRender {
  estimate: RenderEstimate;
  lighter: LighterRender[];
}

/**
 * Before a render starts: how long it will take on this machine (a short probe of the scene
 * by the workers when it may be long: render-probe.ts), and when that is over a minute, the
 * learner's choice of a lighter render or "Render anyway". The host shows `estimating`
 * and `heavy`, and reports how long each measured render really took (`finished`), so
 * that later estimates are corrected by how the earlier ones came true.
 */
export class HeavyRenderCheck implements ReactiveController {
  /** A probe is running: the render starts (or the question appears) when it is done. */
  estimating = false;
  heavy: HeavyRender | null = null;
  /** The check under way: one overtaken by a newer one (or by Render anyway) is aborted, its probe stopped and its answer ignored. */
  private current: AbortController | null = null;
  /** The correction the last estimate was made with: a finished render is recorded without it. */
  private correction = 1;

  constructor(private readonly host: ReactiveControllerHost) {
    host.addController(this);
  }

  /** The window left the page: its probe stops before its next round, and its question goes. */
  hostDisconnected(): void {
    this.settle();
  }

  /** Whether a render of `scene` at its image size needs `mayStart` (a probe): a light one starts at once, without a flash of "Estimating…". */
  needsCheck(scene: Scene, pool: RenderPool): boolean {
    const [width, height] = scene.settings.imageSize;
    return mayBeLong(scene, width, height, pool.size);
  }

  /**
   * Whether a render of `scene` at its image size may start now: not when it is heavy (the
   * question is shown) or when a newer check or render overtook this one. A probe that fails
   * lets the render start, which reports the failure itself.
   */
  async mayStart(scene: Scene, pool: RenderPool): Promise<StartDecision> {
    this.current?.abort();
    const { signal } = (this.current = new AbortController());
    this.update({ estimating: true, heavy: null });
    const [width, height] = scene.settings.imageSize;
    try {
      const meshes = await loadMeshes(meshNamesInScene(scene));
      if (signal.aborted) return { start: false };
      this.correction = sessionCalibration.correction;
      const here = await estimateHere(pool, scene, meshes, width, height, { preview: true, calibration: sessionCalibration, signal });
      if (signal.aborted) return { start: false };
      if (!here) {
        // Another job took the workers (the scene changed under the probe): nothing is started unasked.
        this.update({ estimating: false, heavy: null });
        return { start: false };
      }
      const full = here.estimate(scene, width, height);
      this.update({ estimating: false, heavy: full.heavy ? { estimate: full, lighter: lighterRenders(scene, width, height, here.estimate) } : null });
      return full.heavy ? { start: false } : { start: true, expectedSeconds: here.measured ? full.seconds : null };
    } catch {
      if (signal.aborted) return { start: false };
      this.update({ estimating: false, heavy: null });
      return { start: true, expectedSeconds: null };
    }
  }

  /** The learner chose (Render anyway, a lighter render, Not now): any check under way is dropped. */
  settle(): void {
    this.current?.abort();
    this.current = null;
    this.update({ estimating: false, heavy: null });
  }

  /** A render a probe promised `expectedSeconds` took `ms`: later estimates are corrected by it. */
  finished(expectedSeconds: number, ms: number): void {
    sessionCalibration.record(expectedSeconds / this.correction, ms);
  }

  /**
   * The question: the estimate, lighter renders to pick (`use` applies one's changes and
   * renders, promised its seconds), Render anyway (`renderAnyway`) or Not now.
   */
  note({ estimate, lighter }: HeavyRender, use: (changes: Partial<Scene['settings']>, seconds: number) => void, renderAnyway: (seconds: number) => void) {
    const option = (choice: LighterRender) => {
      const { seconds } = choice.estimate;
      const wait = formatWait(seconds);
      switch (choice.change) {
        case 'supersampling':
          return html`<button @click=${() => use({ supersampling: choice.supersampling }, seconds)}>${msg(str`Supersampling ${choice.supersampling} (about ${wait})`)}</button>`;
        case 'path-samples':
          return html`<button @click=${() => use({ pathSamples: choice.pathSamples }, seconds)}>${choice.pathSamples === 1 ? msg(str`1 path per pixel (about ${wait})`) : msg(str`${choice.pathSamples} paths per pixel (about ${wait})`)}</button>`;
        case 'image-size':
          return html`<button @click=${() => use({ imageSize: [choice.width, choice.height] }, seconds)}>${msg(str`${choice.width} × ${choice.height} pixels (about ${wait})`)}</button>`;
        case 'max-depth':
          return html`<button @click=${() => use({ maxDepth: choice.maxDepth }, seconds)}>${msg(str`Recursion depth ${choice.maxDepth} (about ${wait})`)}</button>`;
      }
    };
    return html`<div class="heavy" role="alert" data-testid="heavy-render">
      <p>${msg(str`On this computer this render would take about ${formatWait(estimate.seconds)} (${formatCount(estimate.rays)} rays). A lighter one shows the same idea:`)}</p>
      <div class="choices">${lighter.map(option)}</div>
      <p><button @click=${() => renderAnyway(estimate.seconds)}>${msg('Render anyway')}</button> <button @click=${() => this.settle()}>${msg('Not now')}</button></p>
    </div>`;
  }

  private update(changes: Pick<HeavyRenderCheck, 'estimating' | 'heavy'>): void {
    Object.assign(this, changes);
    this.host.requestUpdate();
  }
}
