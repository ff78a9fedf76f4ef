import { msg } from '@lit/localize';
import { css, html, LitElement } from 'lit';
import { DEFAULT_SEED, type RenderImage } from '../app/render-job.ts';
import type { RenderPool } from '../app/render-pool.ts';
import { createBrowserRenderPool } from '../app/web-worker-port.ts';
import { loadMeshes } from '../app/load-meshes-browser.ts';
import { meshNamesInScene } from '../scene/mesh-names.ts';
import { defaultScene } from '../scene/scene-defaults.ts';
import { toRgba8 } from '../tracer/quantize.ts';

type Status =
  | { kind: 'loading' }
  | { kind: 'rendering'; phase: 'preview' | 'full'; done: number; total: number }
  | { kind: 'finished'; ms: number; raysPerSecond: number; workers: number }
  | { kind: 'failed'; message: string };

/**
 * @summary The first app shell: a title and the default scene rendered by the real worker
 * pool, with a progressive preview and a progress bar (the lab replaces it with the real UI).
 */
export class RtAppShell extends LitElement {
  static override properties = { status: { state: true } };

  static override styles = css`
    :host {
      display: block;
      max-width: 880px;
      margin: 0 auto;
      padding: calc(var(--rt-space) * 2);
    }
    h1 {
      margin: 0 0 4px;
      font-size: 1.8rem;
    }
    p {
      margin: 0 0 var(--rt-space);
      color: var(--rt-muted);
    }
    figure {
      margin: 0;
      background: var(--rt-surface);
      border: 1px solid var(--rt-border);
      border-radius: var(--rt-radius);
      padding: var(--rt-space);
    }
    canvas {
      display: block;
      width: 100%;
      height: auto;
      border-radius: 6px;
      image-rendering: pixelated;
      background: #000;
    }
    figcaption {
      display: flex;
      align-items: center;
      gap: var(--rt-space);
      margin-top: var(--rt-space);
    }
    progress {
      flex: 1;
      height: 10px;
      accent-color: var(--rt-accent);
    }
    .status {
      min-width: 16em;
      font-variant-numeric: tabular-nums;
    }
    .error {
      color: var(--rt-danger);
    }
    button {
      font: inherit;
      padding: 6px 14px;
      border-radius: 8px;
      border: 0;
      background: var(--rt-accent);
      color: var(--rt-accent-text);
      cursor: pointer;
    }
    button:focus-visible {
      outline: 3px solid var(--rt-text);
      outline-offset: 2px;
    }
  `;

  declare status: Status;
  private pool: RenderPool | null = null;
  private readonly scene = defaultScene();

  constructor() {
    super();
    this.status = { kind: 'loading' };
  }

  override connectedCallback(): void {
    super.connectedCallback();
    this.pool = createBrowserRenderPool();
    void this.startRender();
  }

  override disconnectedCallback(): void {
    super.disconnectedCallback();
    this.pool?.dispose();
    this.pool = null;
  }

  /** Renders the scene, drawing each coarse preview and then the finished image. */
  private async startRender(): Promise<void> {
    const pool = this.pool;
    if (!pool) return;
    try {
      const meshes = await loadMeshes(meshNamesInScene(this.scene));
      const job = pool.render(this.scene, meshes, {
        seed: DEFAULT_SEED,
        onPreview: (image) => this.draw(image),
        onProgress: ({ phase, done, total }) => {
          this.status = { kind: 'rendering', phase, done, total };
          this.draw(job.image);
        },
      });
      const result = await job.done;
      if (result.cancelled) return;
      this.draw(result);
      const rays = result.stats.primary + result.stats.shadow + result.stats.reflect + result.stats.refract;
      this.status = { kind: 'finished', ms: result.ms, raysPerSecond: rays / (result.ms / 1000), workers: result.workers };
    } catch (error) {
      this.status = { kind: 'failed', message: error instanceof Error ? error.message : String(error) };
    }
  }

  private draw(image: RenderImage): void {
    const canvas = this.renderRoot.querySelector('canvas');
    const context = canvas?.getContext('2d');
    if (!canvas || !context) return;
    if (canvas.width !== image.width || canvas.height !== image.height) {
      canvas.width = image.width;
      canvas.height = image.height;
    }
    const rgba = toRgba8(image.rgb, image.width, image.height, this.scene.settings.dithering);
    context.putImageData(new ImageData(new Uint8ClampedArray(rgba), image.width, image.height), 0, 0);
  }

  override render() {
    const [width, height] = this.scene.settings.imageSize;
    return html`
      <h1>${msg('Ray Tracer Quest')}</h1>
      <p>${msg('See every ray a ray tracer shoots. This is the real ray tracer, rendering in your browser.')}</p>
      <figure>
        <canvas width=${width} height=${height} role="img" aria-label=${msg('The rendered image of the default scene')}></canvas>
        <figcaption>${this.caption()}</figcaption>
      </figure>
    `;
  }

  private caption() {
    const status = this.status;
    switch (status.kind) {
      case 'loading':
        return html`<progress aria-label=${msg('Render progress')}></progress><span class="status">${msg('Loading…')}</span>`;
      case 'rendering':
        return html`<progress aria-label=${msg('Render progress')} max=${status.total} value=${status.done}></progress>
          <span class="status">${status.phase === 'preview' ? msg('Quick preview…') : msg(`Rendering: ${Math.round((100 * status.done) / status.total)} %`)}</span>`;
      case 'finished':
        return html`<progress aria-label=${msg('Render progress')} max="1" value="1"></progress>
          <span class="status" data-testid="render-status">${msg(`Done in ${(status.ms / 1000).toFixed(2)} s, ${(status.raysPerSecond / 1e6).toFixed(1)} M rays/s on ${status.workers} workers`)}</span>
          <button @click=${() => void this.startRender()} title=${msg('Render the scene again')}>${msg('Render again')}</button>`;
      case 'failed':
        return html`<span class="status error" role="alert">${msg(`The render failed: ${status.message}`)}</span>
          <button @click=${() => void this.startRender()}>${msg('Try again')}</button>`;
    }
  }
}

customElements.define('rt-app-shell', RtAppShell);

declare global {
  interface HTMLElementTagNameMap {
    'rt-app-shell': RtAppShell;
  }
}
