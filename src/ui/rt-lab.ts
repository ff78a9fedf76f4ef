import { msg } from '@lit/localize';
import { css, html, LitElement } from 'lit';
import type { AppState } from '../app/app-state.ts';
import { initialState } from '../app/app-state.ts';
import { loadMeshes } from '../app/load-meshes-browser.ts';
import type { RenderPool } from '../app/render-pool.ts';
import type { ScreenRays } from '../app/screen-rays.ts';
import { ScreenTracer } from '../app/screen-tracer.ts';
import { Store } from '../app/store.ts';
import { createBrowserRenderPool } from '../app/web-worker-port.ts';
import { defaultScene } from '../scene/scene-defaults.ts';
import type { RayHoverDetail } from '../view/lab-view.ts';
import { RayPool } from '../view/ray-pool.ts';
import './rt-light-panel.ts';
import './rt-object-panel.ts';
import './rt-ray-panel.ts';
import './rt-ray-tooltip.ts';
import './rt-render-window.ts';
import './rt-scene-list.ts';
import type { RtSceneView } from './rt-scene-view.ts';
import './rt-scene-view.ts';
import './rt-screen-preview.ts';
import './rt-theme-toggle.ts';
import type { RtToast } from './rt-toast.ts';
import './rt-toast.ts';
import './rt-tracer-panel.ts';

/**
 * @summary The lab: the 3D view in the centre, editing panels on the left, the game's task
 * area on the right, the render window over the view. Owns the one Store, the render pool
 * for full images and a one-worker pool that traces the camera's pixels for the rays.
 */
export class RtLab extends LitElement {
  static override properties = {
    state: { state: true },
    screenRays: { state: true },
    hover: { state: true },
    renderOpen: { state: true },
  };

  static override styles = css`
    :host {
      display: grid;
      grid-template-columns: minmax(260px, 300px) 1fr minmax(220px, 280px);
      grid-template-rows: auto 1fr;
      height: 100vh;
      overflow: hidden;
    }
    header {
      grid-column: 1 / -1;
      display: flex;
      align-items: center;
      gap: var(--rt-space);
      padding: 6px calc(var(--rt-space) * 2);
      background: var(--rt-surface);
      border-bottom: 1px solid var(--rt-border);
    }
    h1 {
      font-size: 1.15rem;
      margin: 0 auto 0 0;
    }
    .sidebar,
    .tasks {
      overflow-y: auto;
      background: var(--rt-surface);
      padding: var(--rt-space);
      display: flex;
      flex-direction: column;
      gap: var(--rt-space);
    }
    .sidebar {
      border-right: 1px solid var(--rt-border);
    }
    .tasks {
      border-left: 1px solid var(--rt-border);
      color: var(--rt-muted);
    }
    main {
      position: relative;
      min-width: 0;
      min-height: 0;
    }
    rt-scene-view {
      position: absolute;
      inset: 0;
    }
    rt-screen-preview {
      position: absolute;
      left: var(--rt-space);
      bottom: var(--rt-space);
      z-index: 5;
      /* A thumbnail of the camera's image: big enough to click a pixel, small enough to leave the scene in view. */
      width: min(240px, 30%);
    }
    rt-render-window {
      position: absolute;
      inset: var(--rt-space);
      z-index: 10;
    }
    .primary {
      font: inherit;
      min-height: var(--rt-target);
      padding: 0 14px;
      border-radius: 8px;
      border: 0;
      background: var(--rt-accent);
      color: var(--rt-accent-text);
      cursor: pointer;
      font-weight: 600;
    }
    .primary:focus-visible {
      outline: 3px solid var(--rt-focus);
      outline-offset: 2px;
    }
    @media (max-width: 1180px) {
      :host {
        grid-template-columns: minmax(240px, 280px) 1fr;
      }
      .tasks {
        display: none;
      }
    }
  `;

  /** The app's one source of truth (public: tests and the game read it). */
  readonly store = new Store(initialState(defaultScene()));
  declare state: AppState;
  declare screenRays: ScreenRays | null;
  declare hover: RayHoverDetail | null;
  declare renderOpen: boolean;

  private renderPool: RenderPool | null = null;
  private tracePool: RenderPool | null = null;
  private screenTracer: ScreenTracer | null = null;
  private readonly rayPool = new RayPool();
  private readonly cleanup: (() => void)[] = [];

  constructor() {
    super();
    this.state = this.store.state;
    this.screenRays = null;
    this.hover = null;
    this.renderOpen = false;
  }

  override connectedCallback(): void {
    super.connectedCallback();
    this.renderPool = createBrowserRenderPool();
    this.tracePool = createBrowserRenderPool(1);
    const tracer = new ScreenTracer(this.tracePool, loadMeshes);
    tracer.onError = (error) => this.toast(msg(`The rays could not be traced: ${error.message}`), 'error');
    this.screenTracer = tracer;
    this.cleanup.push(
      tracer.subscribe((rays) => {
        this.screenRays = rays;
        this.sceneView()?.labView?.setScreenRays(rays);
        this.redrawRays();
      }),
      this.store.subscribe((state, _action, error) => {
        const previous = this.state;
        this.state = state;
        if (error) this.toast(error, 'error');
        if (state.scene !== previous.scene) tracer.update(state.scene);
        if (state.rays !== previous.rays || state.selectedPixel !== previous.selectedPixel) this.redrawRays();
      }),
    );
    tracer.update(this.state.scene);
  }

  override disconnectedCallback(): void {
    super.disconnectedCallback();
    for (const stop of this.cleanup.splice(0)) stop();
    this.screenTracer?.dispose();
    this.tracePool?.dispose();
    this.renderPool?.dispose();
    this.rayPool.dispose();
  }

  override async firstUpdated(): Promise<void> {
    const view = this.sceneView();
    if (!view) return;
    await view.updateComplete;
    view.labView?.setRayLayer(this.rayPool);
    if (this.screenRays) view.labView?.setScreenRays(this.screenRays);
  }

  private sceneView(): RtSceneView | null {
    return this.renderRoot.querySelector('rt-scene-view');
  }

  private redrawRays(): void {
    this.rayPool.update(this.screenRays, this.state.rays, this.state.selectedPixel);
    const view = this.sceneView();
    if (!view) return;
    // How many rays are drawn, readable from outside (browser tests, curious teachers).
    view.dataset.rayInstances = String(this.rayPool.stats.rays);
    view.dataset.coneInstances = String(this.rayPool.stats.cones);
    view.labView?.requestRender();
  }

  private toast(text: string, tone: 'info' | 'error' = 'info'): void {
    this.renderRoot.querySelector<RtToast>('rt-toast')?.show(text, tone);
  }

  private openRenderWindow(): void {
    this.renderOpen = true;
    this.store.dispatch({ type: 'panel.opened', panel: 'render' });
  }

  override render() {
    const selection = this.state.selection;
    const labView = () => this.sceneView()?.labView ?? null;
    return html`
      <header>
        <h1>${msg('Ray Tracer Quest')}</h1>
        <button class="primary" @click=${this.openRenderWindow} title=${msg('Open the render window and ray trace the whole image')}>
          ${msg('Render image')}
        </button>
        <rt-theme-toggle></rt-theme-toggle>
      </header>
      <aside class="sidebar" aria-label=${msg('Scene and settings')}>
        <rt-scene-list .store=${this.store} allow-editing></rt-scene-list>
        ${selection?.kind === 'light' ? html`<rt-light-panel .store=${this.store}></rt-light-panel>` : html`<rt-object-panel .store=${this.store}></rt-object-panel>`}
        <rt-tracer-panel .store=${this.store}></rt-tracer-panel>
        <rt-ray-panel .store=${this.store}></rt-ray-panel>
      </aside>
      <main>
        <rt-scene-view
          .store=${this.store}
          @ray-hover=${(event: CustomEvent<RayHoverDetail | null>) => (this.hover = event.detail)}
          @view-message=${(event: CustomEvent<string>) => this.toast(event.detail, 'error')}
        ></rt-scene-view>
        <rt-screen-preview .store=${this.store} .rays=${this.screenRays}></rt-screen-preview>
        <rt-ray-tooltip .store=${this.store} .hover=${this.hover?.hover ?? null} .x=${this.hover?.x ?? 0} .y=${this.hover?.y ?? 0}></rt-ray-tooltip>
        <rt-render-window
          .store=${this.store}
          .pool=${this.renderPool}
          .rasterSnapshot=${(width: number, height: number) => labView()?.rasterSnapshot(width, height) ?? new ImageData(width, height)}
          ?open=${this.renderOpen}
          ?hidden=${!this.renderOpen}
          @close=${() => (this.renderOpen = false)}
        ></rt-render-window>
        <rt-toast></rt-toast>
      </main>
      <aside class="tasks" aria-label=${msg('Tasks')}>
        <p>${msg('Your tasks appear here when you play a level. In the lab, explore freely.')}</p>
      </aside>
    `;
  }
}

customElements.define('rt-lab', RtLab);

declare global {
  interface HTMLElementTagNameMap {
    'rt-lab': RtLab;
  }
}
