import { msg, str } from '@lit/localize';
import { css, html, LitElement, nothing, type PropertyValues } from 'lit';
import type { LabState } from '../../lab-state/lab-state.ts';
import { initialState } from '../../lab-state/lab-state.ts';
import { loadMeshes } from '../../render/load-meshes-browser.ts';
import type { RenderPool } from '../../render/render-pool.ts';
import type { ScreenRays } from '../../render/screen-rays.ts';
import { ScreenTracer } from '../../render/screen-tracer.ts';
import { Store } from '../../lab-state/store.ts';
import { createBrowserRenderPool } from '../../render/web-worker-port.ts';
import { loadBrowserCatalog } from '../../app/level-catalog-browser.ts';
import { QuestSession } from '../../app/quest-session.ts';
import type { ShowMeStage } from '../../app/show-me-player.ts';
import type { Assignment } from '../../classroom/assignment.ts';
import { SurveyStore } from '../../classroom/survey-store.ts';
import type { SurveySubmission } from '../../classroom/survey-answers.ts';
import { ALWAYS_SHOWN, UI_PANELS, type LabPanel } from '../../quest/lab-controls.ts';
import type { LevelCatalog } from '../../quest/level-index.ts';
import { MemoryStorage, type KeyValueStorage } from '../../quest/progress-store.ts';
import { badgeName, badgeOfLevel } from '../game/badge-names.ts';
import { PANEL_HOSTS, guideRect, hiddenControlsCss, hiddenToolbarCss, locateGuideTarget, revealGuideTarget, type GuideStage } from './guide-targets.ts';
import type { QuestCommand } from '../game/quest-command.ts';
import type { MapChoice } from '../game/rt-level-map.ts';
import type { ProgressCommand } from '../game/rt-progress-menu.ts';
import type { RtRenderWindow } from './render-window/rt-render-window.ts';
import './rt-guide-ring.ts';
import '../game/rt-level-map.ts';
import '../classroom/rt-participant-dialog.ts';
import '../game/rt-progress-menu.ts';
import '../game/rt-quest-panel.ts';
import '../game/rt-score.ts';
import '../classroom/rt-survey.ts';
import { defaultScene } from '../../scene/scene-defaults.ts';
import type { LabView, RayHoverDetail } from '../../view/lab-view.ts';
import { RayPool } from '../../view/ray-pool.ts';
import './panels/rt-light-panel.ts';
import './panels/rt-object-panel.ts';
import './panels/rt-ray-panel.ts';
import './rt-ray-tooltip.ts';
import './render-window/rt-render-window.ts';
import './panels/rt-scene-list.ts';
import type { RtSceneView } from './rt-scene-view.ts';
import './rt-scene-view.ts';
import './rt-screen-preview.ts';
import '../shell/rt-theme-toggle.ts';
import type { RtToast } from '../shell/rt-toast.ts';
import '../shell/rt-toast.ts';
import './panels/rt-tracer-panel.ts';
import './panels/rt-file-panel.ts';
import './panels/rt-bvh-panel.ts';
import '../classroom/rt-export-menu.ts';
import '../classroom/rt-assignment-done.ts';
import type { Scene } from '../../scene/scene.ts';
import { BvhBoxes } from '../../view/bvh-boxes.ts';

/** The address fragment that opens the free lab instead of the game. */
export const FREE_LAB_HASH = '#free-lab';

/** Every level file, read once per page. */
let catalog: LevelCatalog | null = null;

/** localStorage, or a Map for this visit when the browser blocks it (the session then says progress is not kept). */
function browserStorage(): KeyValueStorage {
  try {
    return localStorage;
  } catch {
    return new MemoryStorage();
  }
}

/**
 * @summary The lab and the game in it: the 3D view in the centre, editing panels on the
 * left, the level's tasks on the right, the render window over the view, the level map
 * over all. Owns the one Store, the quest session (engine, progress, timers), the render
 * pool for full images and a one-worker pool that traces the camera's pixels for the rays.
 * A level shows only the panels it lists; the free lab shows them all.
 *
 * `assignment`: a teacher's assignment (set before the lab connects, by the router): its
 * levels, required tasks, language, participant code and closing survey.
 */
export class RtLab extends LitElement {
  static override properties = {
    state: { state: true },
    screenRays: { state: true },
    hover: { state: true },
    renderOpen: { state: true },
    assignment: { attribute: false },
    sharedScene: { attribute: false },
    game: { state: true },
    welcome: { state: true },
    survey: { state: true },
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
    /* Every area has its cell: the level map, placed over row 2, must not push them into a row of their own. */
    .sidebar {
      grid-area: 2 / 1;
      border-right: 1px solid var(--rt-border);
    }
    main {
      grid-area: 2 / 2;
    }
    .tasks {
      grid-area: 2 / 3;
      border-left: 1px solid var(--rt-border);
      color: var(--rt-muted);
    }
    .your-data {
      margin-top: auto;
      padding-top: var(--rt-space);
      border-top: 1px solid var(--rt-border);
    }
    .your-data h2 {
      font-size: 0.875rem;
      margin: 0 0 var(--rt-space);
      color: var(--rt-muted);
    }
    .header-actions {
      display: flex;
      align-items: center;
      gap: var(--rt-space);
      flex-wrap: wrap;
    }
    .header-actions button:not(.primary),
    .welcome button {
      font: inherit;
      min-height: var(--rt-target);
      padding: 0 12px;
      border-radius: 8px;
      border: 1px solid var(--rt-border);
      background: var(--rt-surface);
      color: var(--rt-text);
      cursor: pointer;
    }
    .header-actions button:focus-visible,
    .welcome button:focus-visible {
      outline: 3px solid var(--rt-focus);
      outline-offset: 2px;
    }
    /* The map covers the whole lab below the header: the level behind it waits. */
    rt-level-map {
      grid-column: 1 / -1;
      grid-row: 2;
      z-index: 30;
      min-height: 0;
    }
    /* The size of the task panel's text below it, so the two read as one column. */
    .welcome {
      padding: 10px;
      border-radius: var(--rt-radius);
      background: var(--rt-accent-soft);
      color: var(--rt-text);
      font-size: 0.875rem;
      line-height: 1.3;
    }
    .welcome p {
      margin: 0 0 8px;
    }
    .empty-sidebar {
      color: var(--rt-muted);
      font-size: 0.875rem;
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
      /* On a card like the view's buttons: its caption must stay readable over a light floor in the dark theme. */
      box-sizing: border-box;
      padding: 4px;
      border-radius: var(--rt-radius);
      background: var(--rt-surface);
      box-shadow: var(--rt-shadow);
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
    /* Narrow screens (1024 px tablets) keep the tasks and narrow both sides; the free lab gives the tasks' room to the view. */
    @media (max-width: 1180px) {
      :host {
        grid-template-columns: minmax(220px, 240px) 1fr minmax(240px, 260px);
      }
      :host([free-lab]) {
        grid-template-columns: minmax(240px, 280px) 1fr;
      }
      :host([free-lab]) .tasks {
        display: none;
      }
    }
  `;

  /** The app's one source of truth (public: tests and the game read it). */
  readonly store = new Store(initialState(defaultScene()));
  declare state: LabState;
  declare screenRays: ScreenRays | null;
  declare hover: RayHoverDetail | null;
  declare renderOpen: boolean;
  declare assignment: Assignment | null;
  /** A scene from a shared link (#/s/…, set by the router): opened in the free lab. */
  declare sharedScene: Scene | null;
  /** Bumped when the game changed, to render it again. */
  declare private game: number;
  /** A newcomer's welcome, shown once over the first level's tasks. */
  declare private welcome: boolean;
  /** The learner's survey answers in this session's progress (read once per session), or null before they hand it in. */
  declare private survey: SurveySubmission | null;
  private session: QuestSession | null = null;
  private readonly sessionCleanup: (() => void)[] = [];
  private readonly narrowedSheets = new WeakMap<ShadowRoot, CSSStyleSheet>();
  private ringKey: string | null = null;
  private ringLocate: (() => DOMRect | null) | null = null;

  private renderPool: RenderPool | null = null;
  private tracePool: RenderPool | null = null;
  private screenTracer: ScreenTracer | null = null;
  private readonly rayPool = new RayPool();
  /** The bounding boxes and BVH boxes of the acceleration levels, drawn in the 3D view. */
  private readonly bvhBoxes = new BvhBoxes(() => this.sceneView()?.labView?.requestRender());
  private readonly cleanup: (() => void)[] = [];

  constructor() {
    super();
    this.state = this.store.state;
    this.screenRays = null;
    this.hover = null;
    this.renderOpen = false;
    this.assignment = null;
    this.sharedScene = null;
    this.game = 0;
    this.welcome = false;
    this.survey = null;
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
        this.bvhBoxes.update(state);
        if (state.rays !== previous.rays || state.selectedPixel !== previous.selectedPixel) this.redrawRays();
      }),
    );
    tracer.update(this.state.scene);
    this.bvhBoxes.update(this.state);
    this.startSession();
  }

  protected override willUpdate(changed: PropertyValues<this>): void {
    if (changed.has('assignment') && changed.get('assignment') !== undefined && this.isConnected) this.startSession();
    if (changed.has('sharedScene') && changed.get('sharedScene') !== undefined && this.isConnected) this.openSharedScene();
  }

  /** The game: progress from storage (a message if it was damaged), then resume, the first level or the map. */
  private startSession(): void {
    this.stopSession();
    catalog ??= loadBrowserCatalog();
    const storage = browserStorage();
    const session = new QuestSession({ store: this.store, catalog, storage, assignment: this.assignment });
    this.session = session;
    this.sessionCleanup.push(
      session.subscribe(() => this.gameChanged()),
      session.attach(document),
      () => session.dispose(),
    );
    // The toast is on the page after the first render.
    const problems = [session.problem?.message, catalog.errors.length > 0 ? msg(str`The level list could not be read: ${catalog.errors.join('; ')}`) : undefined];
    void this.updateComplete.then(() => problems.forEach((problem) => problem && this.toast(problem, 'error')));
    const newcomer = Object.keys(session.engine.progress.levels).length === 0 && session.engine.progress.current === null;
    // #free-lab (a bookmark, the lab's own browser tests) goes straight to the free lab.
    if (location.hash === FREE_LAB_HASH) session.openFreeLab();
    else session.start();
    this.openSharedScene();
    this.welcome = newcomer && session.mode.kind === 'level';
    this.survey = new SurveyStore(storage, session.progressKey).load();
    this.gameChanged();
  }

  /** The shared scene in the free lab (every panel, to look at it and save it); the learner's sandbox is kept until they edit it. */
  private openSharedScene(): void {
    if (!this.sharedScene || !this.session) return;
    this.session.openFreeLab();
    this.store.dispatch({ type: 'scene.loaded', scene: this.sharedScene });
  }

  private stopSession(): void {
    for (const stop of this.sessionCleanup.splice(0)) stop();
    this.session = null;
  }

  private gameChanged(): void {
    const error = this.session?.saveError;
    if (error) this.toast(error, 'error');
    this.toggleAttribute('free-lab', this.session?.mode.kind === 'free-lab');
    this.game++;
  }

  override disconnectedCallback(): void {
    super.disconnectedCallback();
    this.stopSession();
    for (const stop of this.cleanup.splice(0)) stop();
    this.screenTracer?.dispose();
    this.tracePool?.dispose();
    this.renderPool?.dispose();
    this.rayPool.dispose();
    this.bvhBoxes.dispose();
  }

  override async firstUpdated(): Promise<void> {
    const view = this.sceneView();
    if (!view) return;
    await view.updateComplete;
    view.labView?.setRayLayer(this.rayPool);
    view.labView?.setBvhLayer(this.bvhBoxes.object);
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

  private labView(): LabView | null {
    return this.sceneView()?.labView ?? null;
  }

  /** "Show me" performs a solution through these: the real view, the real render window. */
  private readonly stage: ShowMeStage = {
    dispatch: (action) => {
      const error = this.store.dispatch(action);
      if (error) this.toast(error, 'error');
    },
    orbit: () => this.labView()?.orbit(),
    pan: () => this.labView()?.pan(),
    zoom: () => this.labView()?.zoom(),
    flyToCamera: () => this.labView()?.flyToCamera(),
    openRender: () => this.openRenderWindow(),
    render: () => {
      this.openRenderWindow();
      void this.updateComplete.then(() => this.renderRoot.querySelector<RtRenderWindow>('rt-render-window')?.startRender());
    },
    openPanel: (panel) => this.store.dispatch({ type: 'panel.opened', panel }),
  };

  private onQuestCommand(command: QuestCommand): void {
    const session = this.session;
    if (!session) return;
    const engine = session.engine;
    switch (command.kind) {
      case 'next':
        engine.next();
        return;
      case 'answer':
        engine.answerQuiz(command.task, command.choice);
        return;
      case 'hint':
        engine.askHint(command.task);
        return;
      case 'show-me':
        session.showMe(command.task, this.stage);
        return;
      case 'skip':
        engine.skip(command.task);
        return;
      case 'explain':
        engine.expandExplanation(command.task);
        return;
      case 'next-level': {
        const next = session.nextLevel();
        if (next) this.openLevel(next);
        return;
      }
      case 'map':
        session.openMap();
        return;
    }
  }

  private openLevel(id: string): void {
    this.renderOpen = false;
    this.welcome = false;
    const opened = this.session?.openLevel(id);
    if (opened && !opened.ok) this.toast(opened.reason === 'locked' ? msg('That level is still locked: finish the one before it first.') : msg('That level cannot be played: its file has problems.'), 'error');
  }

  private onMapChoice(choice: MapChoice): void {
    const session = this.session;
    if (!session) return;
    if (choice.kind === 'level') this.openLevel(choice.id);
    else if (choice.kind === 'free-lab') {
      this.renderOpen = false;
      session.openFreeLab();
    } else {
      const current = session.engine.progress.current?.level;
      if (current) this.openLevel(current);
    }
  }

  private onProgressCommand(command: ProgressCommand): void {
    const session = this.session;
    if (!session) return;
    switch (command.kind) {
      case 'locale':
        session.setLocale(command.locale);
        return;
      case 'export': {
        const link = document.createElement('a');
        link.href = URL.createObjectURL(new Blob([session.exportText()], { type: 'application/json' }));
        link.download = 'ray-tracer-quest-progress.json';
        link.click();
        setTimeout(() => URL.revokeObjectURL(link.href), 1000);
        return;
      }
      case 'import': {
        const imported = session.importText(command.text);
        if (imported.ok) this.toast(msg(str`Progress imported from ${command.fileName}.`));
        else this.toast(msg(str`${command.fileName} is not a progress file this app can read, so nothing changed:\n${imported.errors.slice(0, 3).join('\n')}`), 'error');
        return;
      }
      case 'reset':
        session.reset();
        this.toast(msg('Your progress was reset. Start again from the level map.'));
        return;
    }
  }

  /** The panels on screen: a level's own choice (plus the view and its screen), or all of them. */
  private shownPanels(): ReadonlySet<LabPanel> {
    const level = this.session?.mode.kind === 'level' ? this.session.engine.level?.level : undefined;
    return new Set<LabPanel>(level ? [...ALWAYS_SHOWN, ...level.ui.panels] : [...ALWAYS_SHOWN, ...UI_PANELS]);
  }

  /** Hides the controls a level leaves out of a panel (and the gizmo buttons when it shows no gizmo), after each render. */
  private narrowControls(): void {
    const level = this.session?.mode.kind === 'level' ? this.session.engine.level?.level : undefined;
    const controls = level?.ui.controls;
    const apply = (host: Element | null, text: string) => {
      const root = host?.shadowRoot;
      if (!root) return;
      let sheet = this.narrowedSheets.get(root);
      if (!sheet) {
        sheet = new CSSStyleSheet();
        this.narrowedSheets.set(root, sheet);
        root.adoptedStyleSheets = [...root.adoptedStyleSheets, sheet];
      }
      sheet.replaceSync(text);
    };
    // Panels whose controls a level can narrow: their shadow roots get a stylesheet hiding the rest.
    for (const [panel, tag] of Object.entries(PANEL_HOSTS) as [keyof typeof PANEL_HOSTS, string][]) apply(this.renderRoot.querySelector(tag), hiddenControlsCss(panel, controls?.[panel]));
    const toolbar = this.sceneView()?.shadowRoot?.querySelector('rt-view-toolbar') ?? null;
    apply(toolbar, level ? hiddenToolbarCss(level.ui.panels.includes('gizmo'), controls?.gizmo) : '');
  }

  private guideStage(): GuideStage {
    const view = this.labView();
    return {
      root: this.renderRoot as ShadowRoot,
      project: (point) => view?.projectToView(point) ?? null,
      canvas: this.sceneView()?.shadowRoot?.querySelector('canvas') ?? null,
      scene: this.store.state.scene,
    };
  }

  /** The ring follows the engine's `ring`: a new target is revealed (sections opened, scrolled to) once. */
  private updateRing(): void {
    const target = this.session?.mode.kind === 'level' ? (this.session.engine.level?.ring ?? null) : null;
    if (target === this.ringKey) return;
    this.ringKey = target;
    const location = target ? locateGuideTarget(target) : undefined;
    this.ringLocate = location ? () => guideRect(location, this.guideStage()) : null;
    if (location) {
      revealGuideTarget(location, this.guideStage());
      // A section just opened lays out on its next render: scroll once more when it has.
      setTimeout(() => revealGuideTarget(location, this.guideStage()), 150);
    }
    this.requestUpdate();
  }

  protected override updated(): void {
    this.narrowControls();
    this.updateRing();
  }

  override render() {
    const selection = this.state.selection;
    const session = this.session;
    const mode = session?.mode ?? { kind: 'map' as const };
    const engine = session?.engine;
    const locale = session?.locale ?? 'en';
    const panels = this.shownPanels();
    const shows = (panel: LabPanel) => panels.has(panel);
    const labView = () => this.labView();
    const catalogNow = session?.catalog ?? { chapters: [], errors: [] };
    const badges = engine?.badges ?? [];
    const sidebar = [
      shows('scene-list') ? html`<rt-scene-list .store=${this.store} ?allow-editing=${shows('add-remove')}></rt-scene-list>` : nothing,
      selection?.kind === 'light' && shows('light')
        ? html`<rt-light-panel .store=${this.store}></rt-light-panel>`
        : shows('object')
          ? html`<rt-object-panel .store=${this.store}></rt-object-panel>`
          : shows('light')
            ? html`<rt-light-panel .store=${this.store}></rt-light-panel>`
            : nothing,
      shows('tracer') ? html`<rt-tracer-panel .store=${this.store}></rt-tracer-panel>` : nothing,
      shows('rays') ? html`<rt-ray-panel .store=${this.store}></rt-ray-panel>` : nothing,
      shows('bvh') ? html`<rt-bvh-panel .store=${this.store}></rt-bvh-panel>` : nothing,
      shows('file') ? html`<rt-file-panel .store=${this.store}></rt-file-panel>` : nothing,
    ].filter((part) => part !== nothing);
    return html`
      <header>
        <h1>${msg('Ray Tracer Quest')}</h1>
        <div class="header-actions">
          <rt-score .points=${engine?.points ?? 0} .badges=${badges.map((earned) => badgeName(earned.badge, catalogNow, locale))}></rt-score>
          <button data-command="levels" @click=${() => session?.openMap()} title=${msg('The level map: chapters, levels and your progress')}>${msg('Levels')}</button>
          ${shows('render')
            ? html`<button class="primary" data-command="render-open" @click=${this.openRenderWindow} title=${msg('Open the render window and ray trace the whole image')}>
                ${msg('Render image')}
              </button>`
            : nothing}
          <rt-progress-menu locale=${locale} @progress-command=${(event: CustomEvent<ProgressCommand>) => this.onProgressCommand(event.detail)}></rt-progress-menu>
          <rt-theme-toggle></rt-theme-toggle>
        </div>
      </header>
      <aside class="sidebar" aria-label=${msg('Scene and settings')}>
        ${sidebar.length > 0 ? sidebar : html`<p class="empty-sidebar">${msg('This level needs only the 3D view. More panels appear in later levels.')}</p>`}
      </aside>
      <main>
        <rt-scene-view
          .store=${this.store}
          @ray-hover=${(event: CustomEvent<RayHoverDetail | null>) => (this.hover = event.detail)}
          @view-message=${(event: CustomEvent<string>) => this.toast(event.detail, 'error')}
        ></rt-scene-view>
        ${shows('screen-preview') ? html`<rt-screen-preview .store=${this.store} .rays=${this.screenRays}></rt-screen-preview>` : nothing}
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
      <aside class="tasks" aria-label=${msg('Tasks')} @quest-command=${(event: CustomEvent<QuestCommand>) => this.onQuestCommand(event.detail)}>
        ${this.tasksColumn()}
        ${session ? this.exportMenu(session) : nothing}
      </aside>
      ${mode.kind === 'map' && session
        ? html`<rt-level-map
            .chapters=${engine?.map() ?? []}
            locale=${locale}
            .current=${engine?.progress.current?.level ?? null}
            ?closable=${engine?.progress.current != null}
            heading=${this.assignment?.title ?? ''}
            @map-choice=${(event: CustomEvent<MapChoice>) => this.onMapChoice(event.detail)}
          ></rt-level-map>`
        : nothing}
      <rt-guide-ring .locate=${this.ringLocate}></rt-guide-ring>
      ${session?.needsParticipantCode
        ? html`<rt-participant-dialog heading=${this.assignment?.title ?? ''} @participant-code=${(event: CustomEvent<string>) => session.setParticipantCode(event.detail)}></rt-participant-dialog>`
        : nothing}
    `;
  }

  /** Downloads of the learner's own timings (CSV, JSON, xAPI) for their teacher. */
  private exportMenu(session: QuestSession) {
    return html`<section class="your-data" aria-label=${msg('Your data')}>
      <h2>${msg('Your data for your teacher')}</h2>
      <rt-export-menu
        .progress=${() => session.engine.progress}
        .participant=${session.context.participantCode}
        .attemptId=${session.context.attemptId}
        .assignment=${this.assignment}
        .survey=${this.survey}
        @export-failed=${(event: CustomEvent<string>) => this.toast(event.detail, 'error')}
      ></rt-export-menu>
    </section>`;
  }

  private tasksColumn() {
    const session = this.session;
    const view = session?.mode.kind === 'level' ? session.engine.level : null;
    const surveyId = this.assignment?.survey;
    if (surveyId && session?.allPassed && !this.survey && customElements.get('rt-survey')) {
      return html`<rt-survey
        .surveyId=${surveyId}
        locale=${session.locale}
        @survey-submitted=${(event: CustomEvent<SurveySubmission>) => {
          new SurveyStore(browserStorage(), session.progressKey).save(event.detail);
          this.survey = event.detail;
          this.toast(msg('Thank you! Your answers are saved. Download your data below for your teacher.'));
        }}
      ></rt-survey>`;
    }
    if (session?.mode.kind === 'free-lab') {
      return html`<h2>${msg('Free lab')}</h2>
        <p>${msg('Build and explore your own scene: every panel is here, and your scene is kept for next time.')}</p>
        <button class="primary" @click=${() => session.openMap()}>${msg('Level map')}</button>`;
    }
    if (session?.mode.kind === 'finished') {
      return html`<rt-assignment-done heading=${this.assignment?.title ?? ''} @open-map=${() => session.openMap()}></rt-assignment-done>`;
    }
    if (!session || !view) {
      return html`<p>${msg('Your tasks appear here when you play a level. In the free lab, explore freely.')}</p>
        <button class="primary" @click=${() => session?.openMap()}>${msg('Level map')}</button>`;
    }
    const { level } = view;
    const earned = session.engine.badges.filter((earnedBadge) => badgeOfLevel(earnedBadge.badge, level.id, level.chapter));
    return html`
      ${this.welcome
        ? html`<div class="welcome" role="status">
            <p><strong>${msg('Welcome to Ray Tracer Quest!')}</strong></p>
            <p>${msg('Do the tasks below, one at a time. Stuck? Press "Hint". The Levels button shows all levels.')}</p>
            <button @click=${() => (this.welcome = false)}>${msg('Got it')}</button>
          </div>`
        : nothing}
      <rt-quest-panel
        .view=${view}
        locale=${session.locale}
        ?has-next-level=${session.nextLevel() !== undefined}
        .badges=${earned.map((earnedBadge) => badgeName(earnedBadge.badge, session.catalog, session.locale))}
      ></rt-quest-panel>
    `;
  }
}

customElements.define('rt-lab', RtLab);

declare global {
  interface HTMLElementTagNameMap {
    'rt-lab': RtLab;
  }
}
