import { msg, str } from '@lit/localize';
import { issueText } from '../../i18n/issue-text.ts';
import { ContextProvider } from '@lit/context';
import { html, nothing, type PropertyValues } from 'lit';
import { LocalizedElement } from '../controls/localized-element.ts';
import { LabServices, type LoadProblem } from '../../app/lab-services.ts';
import { labLoadProblems, withProblem } from './lab-load-problem.ts';
import type { ShowMeStage } from '../../app/show-me-player.ts';
import type { Assignment } from '../../classroom/assignment.ts';
import { showToast } from './toast-place.ts';
import { consentText } from '../../classroom/consent-text.ts';
import type { LabState } from '../../lab-state/lab-state.ts';
import type { Store } from '../../lab-state/store.ts';
import { type UiPanel, guideIds } from '../../quest/lab-controls.ts';
import { loadMeshes } from '../../render/load-meshes-browser.ts';
import { createBrowserRenderPool } from '../../render/web-worker-port.ts';
import type { Scene } from '../../scene/scene.ts';
import { sameValue } from '../../util/same-value.ts';
import type { LabView, RayHoverDetail } from '../../view/lab-view.ts';
import type { RayFocus } from '../../view/ray-focus.ts';
import { badgeName } from '../game/badge-names.ts';
import type { QuestCommand } from '../game/quest-command.ts';
import type { MapChoice } from '../game/rt-level-map.ts';
import type { ProgressCommand } from '../game/rt-progress-menu.ts';
import { GuideHostController } from './guide-host.ts';
import { GuideRingDriver } from './guide-ring-driver.ts';
import type { ScreenBox } from './guide-targets.ts';
import { labLayout } from './lab-layout.css.ts';
import { taskColumn } from './task-column.ts';
import { levelPanels } from './level-panels.ts';
import { labSidebar } from './lab-sidebar.ts';
import { viewLegendBox } from './view-legend.ts';
import { sideSwitch } from './side-switch.ts';
import { conceptTestPage } from './concept-test-page.ts';
import { surveyPage } from './survey-page.ts';
import { QuestController } from './quest-controller.ts';
import type { RtRenderWindow } from './render-window/rt-render-window.ts';
import type { RtSceneView } from './rt-scene-view.ts';
import { storeContext } from './store-context.ts';
import { providePictures } from './picture-providers.ts';
import { loadAfterFirstScreen, ON_DEMAND_PANELS, withRenderWindow } from './lab-elements.ts';
import { ViewCoverController } from './view-cover.ts';
import { PreviewPlaceController } from './preview-place.ts';
import { RenderWindowWatch } from './render-window/render-window-watch.ts';

export { FREE_LAB_HASH } from './quest-controller.ts';

/**
 * @summary The lab and the game in it: the 3D view in the centre, editing panels on the left,
 * the level's tasks on the right, the render window over the view, the level map over all.
 * Layout only: the services (store, pools, screen tracer, ray pool) are a LabServices, the
 * game a QuestController, the hint ring a GuideRingDriver. The store reaches the elements
 * inside through `storeContext`. A level shows only the panels and controls it lists.
 *
 * `assignment`: a teacher's assignment (set before the lab connects, by the router);
 * `sharedScene`: a scene from a shared link (#/s/…), opened in the free lab. For tests and
 * tools: `store`, `guideRect(target)` and `guideElements(target)` (where the hint ring
 * would go for a guide target, and the elements that carry it).
 */
export class RtLab extends LocalizedElement {
  static override properties = {
    hover: { state: true },
    renderOpen: { state: true },
    legendOpen: { state: true },
    panelsShown: { type: Boolean, reflect: true, attribute: 'panels-shown' },
    assignment: { attribute: false },
    sharedScene: { attribute: false },
  };

  static override styles = labLayout;

  declare private hover: RayHoverDetail | null;
  declare private renderOpen: boolean;
  /** Whether the ray legend over the view is open where it folds away (phones). */
  declare private legendOpen: boolean;
  /** On a small screen, whether the column beside the view shows the panels instead of the tasks (side-switch.ts). */
  declare panelsShown: boolean;
  declare assignment: Assignment | null;
  declare sharedScene: Scene | null;

  private services: LabServices;
  private servicesDisposed = false;
  private readonly storeProvider: ContextProvider<typeof storeContext, this>;
  private readonly game = new QuestController(this);
  private readonly ring = new GuideRingDriver(this, () => ({
    project: (point) => this.labView()?.projectToView(point) ?? null,
    canvas: this.sceneView()?.labView?.canvas ?? null,
    scene: this.store.state.scene,
    panelsButton: this.panelsShown ? null : this.renderRoot.querySelector('[data-command="show-panels"]'),
  }));
  private readonly cleanup: (() => void)[] = [];

  constructor() {
    super();
    this.hover = null;
    this.renderOpen = false;
    this.legendOpen = false;
    this.panelsShown = false;
    this.assignment = null;
    this.sharedScene = null;
    this.services = this.createServices();
    this.storeProvider = new ContextProvider(this, { context: storeContext, initialValue: this.services.store });
    providePictures(this, () => ({ services: this.services, levelScene: this.level()?.scene, view: this.labView() }));
    new GuideHostController(this);
    new ViewCoverController(this, () => ({
      view: this.sceneView(),
      overlays: [...this.renderRoot.querySelectorAll('rt-screen-preview, rt-ray-debugger')],
      tell: (px) => this.labView()?.setCoveredBottom(px),
    }));
    new PreviewPlaceController(this, () => ({ view: this.labView(), preview: this.renderRoot.querySelector('rt-screen-preview') }));
  }

  /** The app's one source of truth. */
  get store(): Store {
    return this.services.store;
  }

  /** Where the hint ring would go for `target` now (viewport px), or null when it is not on screen. */
  guideRect(target: string): ScreenBox | null {
    return this.ring.rect(target);
  }

  /** The elements on the page that carry the guide id `target` (none when the level hides the control). */
  guideElements(target: string): Element[] {
    return this.ring.elements(target);
  }

  /** Code the lab could not load (only a reload helps: it stays said). */
  private loadProblems: readonly LoadProblem[] = [];

  private createServices(): LabServices {
    return new LabServices({
      createPool: createBrowserRenderPool,
      loadMeshes,
      report: (text, tone) => this.toast(text, tone),
      traceFailed: (error) => msg(str`The rays could not be traced: ${error.message}`),
      cannotLoad: (problem) => ((this.loadProblems = withProblem(this.loadProblems, problem)), this.requestUpdate()),
    });
  }

  override connectedCallback(): void {
    // Back on the page after leaving it: new workers (and a new lab) before the game starts.
    if (this.servicesDisposed) {
      this.services = this.createServices();
      this.servicesDisposed = false;
      this.storeProvider.setValue(this.services.store);
    }
    super.connectedCallback();
    loadAfterFirstScreen(this);
    this.cleanup.push(
      this.services.subscribe(() => this.requestUpdate()),
      this.store.subscribe(() => this.requestUpdate()),
    );
  }

  override disconnectedCallback(): void {
    super.disconnectedCallback();
    for (const stop of this.cleanup.splice(0)) stop();
    this.services.dispose();
    this.servicesDisposed = true;
  }

  protected override willUpdate(changed: PropertyValues<this>): void {
    this.loadOnDemandPanels();
    // The gizmo's option buttons make the view's top bar two rows high in a small view (lab-compact.css.ts).
    const { gizmo } = levelPanels(this.level());
    this.toggleAttribute('gizmo-options', gizmo === undefined || gizmo.includes('space') || gizmo.includes('snap'));
    // Another assignment starts the game again. The one it connected with has started it, and the
    // same assignment decoded again (a new object) must not: a second start would lose what the
    // first one read (that the saved record was damaged, say).
    if (changed.has('assignment') && this.isConnected && !sameValue(this.game.session?.assignment ?? null, this.assignment)) this.game.start();
    if (changed.has('sharedScene') && this.sharedScene) this.game.openSharedScene(this.sharedScene);
    this.closeRenderWindowWhenInTheWay();
  }

  /**
   * The render window covers the 3D view and the pixel preview. It stays open while the
   * learner looks at the image, and closes only when a task's view frames something in the
   * 3D view or a hint rings something under it; the toast says why, and how to bring it back.
   */
  private closeRenderWindowWhenInTheWay(): void {
    if (!this.renderWindowWatch.mustClose({ ring: this.currentRing(), look: this.store.state.look }, this.renderOpen)) return;
    this.renderOpen = false;
    this.toast(msg('The render window was closed to show the 3D view this task needs. Open it again with Render image.'));
  }
  private readonly renderWindowWatch = new RenderWindowWatch(
    () => this.renderRoot.querySelector('rt-render-window'),
    (target) => this.guideElements(target),
  );
  /** What the hint ring points at in the level being played, or null. */
  private currentRing(): string | null {
    const session = this.game.session;
    return session?.mode.kind === 'level' ? (session.engine.level?.ring ?? null) : null;
  }

  protected override updated(): void {
    this.ring.follow(this.currentRing());
    // How many rays are drawn, readable from outside (browser tests, curious teachers).
    const view = this.sceneView();
    if (view) {
      view.dataset.rayInstances = String(this.services.drawn.rays);
      view.dataset.coneInstances = String(this.services.drawn.cones);
    }
  }

  /** The 3D view has loaded: the services draw into it, and the counts below follow. */
  private readonly onViewReady = async (event: CustomEvent<LabView>) => {
    // The count below follows the ray budget too (ray-budget.ts), which changes without a new screen.
    event.detail.on('thinning', () => this.requestUpdate());
    await this.services.attachView(event.detail);
    this.requestUpdate();
  };

  /** The on-demand panels the level shows, loaded the first time; one that fails is drawn as its message. */
  private loadOnDemandPanels(): void {
    const { panels } = levelPanels(this.level());
    for (const [panel, code] of Object.entries(ON_DEMAND_PANELS)) {
      if (panels.has(panel as UiPanel) && code?.state === 'idle') code.load().catch(() => this.requestUpdate());
    }
  }

  private sceneView(): RtSceneView | null {
    return this.renderRoot.querySelector('rt-scene-view');
  }

  private labView(): LabView | null {
    return this.sceneView()?.labView ?? null;
  }

  toast(text: string, tone: 'info' | 'error' = 'info'): void {
    showToast(this.renderRoot, text, tone);
  }

  closeRenderWindow(): void {
    this.renderOpen = false;
  }

  modeChanged(freeLab: boolean): void {
    this.toggleAttribute('free-lab', freeLab);
  }

  private openRenderWindow(): void {
    this.renderOpen = true;
    withRenderWindow(this);
    this.store.dispatch({ type: 'panel.opened', panel: 'render' });
  }

  /** "Show me" performs a solution through these: the real view, the real render window. */
  readonly stage: ShowMeStage = {
    dispatch: (action) => {
      const error = this.store.dispatch(action);
      if (error) this.toast(error.map(issueText).join('\n'), 'error');
    },
    orbit: () => this.labView()?.orbit(),
    pan: () => this.labView()?.pan(),
    zoom: () => this.labView()?.zoom(),
    flyToCamera: () => this.labView()?.flyToCamera(),
    openRender: () => this.openRenderWindow(),
    render: () => {
      this.openRenderWindow();
      withRenderWindow(this, () => this.updateComplete.then(() => this.renderRoot.querySelector<RtRenderWindow>('rt-render-window')?.startRender()));
    },
    openPanel: (panel) => this.store.dispatch({ type: 'panel.opened', panel }),
    debug: (action) => this.renderRoot.querySelector('rt-ray-debugger')?.perform(action),
  };

  /** Shows the panels (or the tasks) in a small screen's column; a control the hint rings there is brought into view. */
  private readonly showPanels = (panels: boolean) => {
    this.panelsShown = panels;
    void this.updateComplete.then(() => this.ring.reveal());
  };

  /** The ray debugger's pixel, traced with its terms, and drawn in 3D (stable functions: lit compares them). */
  private readonly traceWithTerms = (x: number, y: number) => this.services.traceWithTerms(x, y);
  private readonly showRayFocus = (focus: RayFocus | null) => {
    const opening = focus !== null && !this.focusShown;
    this.focusShown = focus !== null;
    this.services.setRayFocus(focus);
    // The open debugger covers the view's lower part: as it opens, its pixel's rays are
    // framed in the part above, once its size is known (two frames: layout, then the cover's measure).
    if (opening && this.store.state.selectedPixel) requestAnimationFrame(() => requestAnimationFrame(() => this.labView()?.showPixelRays()));
  };
  /** Whether the ray debugger is drawing its pixel now. */
  private focusShown = false;

  /** The level being played, if one is. */
  private level() {
    const session = this.game.session;
    return session?.mode.kind === 'level' ? session.engine.level?.level : undefined;
  }

  override render() {
    const state: LabState = this.store.state;
    const session = this.game.session;
    const engine = session?.engine;
    const locale = session?.locale ?? 'en';
    const { panels, controls, gizmo, movable, viewLegend } = levelPanels(this.level());
    const shows = (panel: UiPanel) => panels.has(panel);
    const catalog = session?.catalog ?? { chapters: [], errors: [] };
    const sidebar = labSidebar(state, { panels, controls, movable });
    return html`
      <header>
        <h1>${msg('Ray Tracer Quest')}</h1>
        <div class="header-actions">
          <rt-score .points=${engine?.points ?? 0} .badges=${(engine?.badges ?? []).map((earned) => badgeName(earned.badge, catalog, locale))}></rt-score>
          <button data-command="levels" @click=${() => session?.openMap()} title=${msg('The level map: chapters, levels and your progress')}>${msg('Levels')}</button>
          ${
            shows('render')
              ? html`<button class="primary" data-command="render-open" data-guide=${guideIds('render.open')} @click=${this.openRenderWindow} title=${msg('Open the render window and ray trace the whole image')}>
                ${msg('Render image')}
              </button>`
              : nothing
          }
          <rt-progress-menu
            locale=${locale}
            ?color-blind=${state.rays.colorBlindPalette}
            .saveProblem=${this.game.saveNote}
            .damagedSaves=${session?.damagedSaves.all ?? []}
            @progress-command=${(event: CustomEvent<ProgressCommand>) => this.game.progress(event.detail)}
          ></rt-progress-menu>
          <rt-theme-toggle></rt-theme-toggle>
        </div>
      </header>
      ${sideSwitch(this.panelsShown, this.showPanels)}
      <aside class="sidebar" aria-label=${msg('Scene and settings')}>
        ${sidebar.length > 0 ? sidebar : html`<p class="empty-sidebar">${msg('This level needs only the 3D view. More panels appear in later levels.')}</p>`}
      </aside>
      <main>
        <rt-scene-view
          .gizmoControls=${gizmo}
          .movable=${movable}
          @ray-hover=${(event: CustomEvent<RayHoverDetail | null>) => (this.hover = event.detail)}
          @view-message=${(event: CustomEvent<string>) => this.toast(event.detail, 'error')}
          @view-ready=${this.onViewReady}
          @view-pads=${(event: CustomEvent<boolean>) => this.toggleAttribute('pads-open', event.detail)}
        ></rt-scene-view>
        ${labLoadProblems(this.loadProblems, shows('debugger'))}
        ${shows('screen-preview') ? html`<rt-screen-preview .rays=${this.services.screenRays}></rt-screen-preview>` : nothing}
        ${viewLegend && (state.rays.showRays || (state.scene.settings.integrator === 'path' && state.selectedPixel)) ? viewLegendBox(this.legendOpen, () => (this.legendOpen = !this.legendOpen)) : nothing}
        ${
          shows('debugger')
            ? html`<rt-ray-debugger
              .shownControls=${controls('debugger')}
              .screenRays=${this.services.screenRays}
              .tracePixel=${this.traceWithTerms} .tracePaths=${this.services.tracePaths}
              .showFocus=${this.showRayFocus}
            ></rt-ray-debugger>`
            : nothing
        }
        <rt-ray-tooltip .hover=${this.hover?.hover ?? null} .x=${this.hover?.x ?? 0} .y=${this.hover?.y ?? 0}></rt-ray-tooltip>
        <rt-render-window
          .pool=${this.services.renderPool}
          .rasterSnapshot=${(width: number, height: number) => this.labView()?.rasterSnapshot(width, height) ?? new ImageData(width, height)}
          ?open=${this.renderOpen}
          ?hidden=${!this.renderOpen}
          @close=${() => (this.renderOpen = false)}
        ></rt-render-window>
        <rt-toast></rt-toast>
      </main>
      <aside class="tasks" aria-label=${msg('Tasks')} @quest-command=${(event: CustomEvent<QuestCommand>) => this.game.quest(event.detail)}>
        ${taskColumn(this.game, this.assignment, (text, tone) => this.toast(text, tone))}
      </aside>
      ${
        session?.mode.kind === 'map'
          ? html`<rt-level-map
            .chapters=${engine?.map() ?? []}
            locale=${locale}
            .current=${engine?.progress.current?.level ?? null}
            ?closable=${engine?.progress.current != null}
            heading=${this.assignment?.title ?? ''}
            @map-choice=${(event: CustomEvent<MapChoice>) => this.game.map(event.detail)}
          ></rt-level-map>`
          : nothing
      }
      ${this.renderOpen ? nothing : [conceptTestPage(this.game, (text, tone) => this.toast(text, tone)), surveyPage(this.game, this.assignment)]}
      <rt-guide-ring .locate=${this.ring.locate}></rt-guide-ring>
      ${
        session?.needsParticipantCode
          ? html`<rt-participant-dialog heading=${this.assignment?.title ?? ''} consent=${consentText(this.assignment)} note=${this.game.contextNote} @participant-code=${(event: CustomEvent<string>) => session.setParticipantCode(event.detail)}></rt-participant-dialog>`
          : nothing
      }
    `;
  }
}

customElements.define('rt-lab', RtLab);

declare global {
  interface HTMLElementTagNameMap {
    'rt-lab': RtLab;
  }
}
