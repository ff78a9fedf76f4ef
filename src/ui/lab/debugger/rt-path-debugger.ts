import { msg, str } from '@lit/localize';
import { css, html, type PropertyValues } from 'lit';
import { findPathVertex, pathRayOf } from '../../../debugger/path-goals.ts';
import { meanOfPaths, pathRows, type PathVertexRow } from '../../../debugger/path-steps.ts';
import type { DebuggerAction, LabAction } from '../../../lab-state/lab-action.ts';
import type { ScreenRays } from '../../../render/screen-rays.ts';
import type { RenderSettings, Scene } from '../../../scene/scene.ts';
import { itemName } from '../scene-names.ts';
import { LAB_PATH_COUNT } from '../../../tracer/lab-path-count.ts';
import type { LabPaths } from '../../../tracer/lab-paths.ts';
import { pathFocus, pathTrees, type PathTrees } from '../../../view/path-focus.ts';
import type { RayFocus } from '../../../view/ray-focus.ts';
import { pathVertexOfRay } from '../../../view/path-vertex-pick.ts';
import type { RayNode } from '../../../tracer/ray-tree.ts';
import { LocalizedElement } from '../../controls/localized-element.ts';
import { colorText } from './debug-numbers.ts';
import { eventName, survivalText, vertexText } from './path-debugger-text.ts';
import { pathTable, pathTableStyles, vertexEstimate } from './path-debugger-table.ts';

/** Keys → moves: ← → along the path, ↑ ↓ to the previous or next path, Home and End to its ends. */
const KEY_MOVES: Readonly<Record<string, readonly [path: number, vertex: number | 'start' | 'end']>> = {
  ArrowRight: [0, 1],
  ArrowLeft: [0, -1],
  ArrowDown: [1, 'start'],
  ArrowUp: [-1, 'start'],
  Home: [0, 'start'],
  End: [0, 'end'],
};

/**
 * @summary The ray debugger in path mode (path-tracing spec §5): the selected pixel's first
 * few sample paths drawn in the 3D view, growing vertex by vertex, and one path stepped
 * through as the rendering equation's estimate: at each vertex its event, f·cosθ/pdf, the
 * throughput so far, what light sampling and light seen directly added, and the path's sum,
 * which ends at its contribution; under it, the pixel as the mean of all its paths.
 *
 * `pixel`, `settings` (the scene's), `screenRays` (a new screen traces the paths again),
 * `tracePaths` (the lab's services), `showFocus` (draws in 3D), `report` (each move as
 * `debugger.stepped`, debugger/path-goals.ts). Carries `data-path` and
 * `data-vertex` for tests.
 */
export class RtPathDebugger extends LocalizedElement {
  static override properties = {
    pixel: { attribute: false },
    settings: { attribute: false },
    scene: { attribute: false },
    screenRays: { attribute: false },
    tracePaths: { attribute: false },
    showFocus: { attribute: false },
    report: { attribute: false },
    paths: { state: true },
    path: { state: true },
    vertex: { state: true },
    problem: { state: true },
  };

  static override styles = [
    pathTableStyles,
    css`
    :host {
      display: flex;
      flex-direction: column;
      gap: 4px;
      min-height: 0;
      flex: 1;
      overflow-y: auto;
      font-size: 0.8rem;
    }
    .controls {
      display: flex;
      flex-wrap: wrap;
      align-items: center;
      gap: 6px;
    }
    .controls button {
      min-height: 30px;
      padding: 0 10px;
    }
    .muted {
      color: var(--rt-muted);
    }
    .vertex-choice select {
      min-height: 30px;
      margin-left: 4px;
    }
    p {
      margin: 0;
    }
    /* At 1366×768 a diffuse vertex's estimate left the table no height at all: it keeps two rows, the dock scrolls. */
    .table {
      flex: 1;
      min-height: 5.5em;
      overflow-y: auto;
    }
  `,
  ];

  declare pixel: readonly [number, number] | null;
  declare settings: RenderSettings | null;
  /** The scene, for its objects' and lights' names (the rows keep ids, as goals read them). */
  declare scene: Scene | null;
  declare screenRays: ScreenRays | null;
  declare tracePaths: ((x: number, y: number, keep: number) => Promise<LabPaths>) | null;
  declare showFocus: ((focus: RayFocus | null) => void) | null;
  declare report: ((action: LabAction) => void) | null;
  declare private paths: LabPaths | null;
  declare private path: number;
  declare private vertex: number;
  declare private problem: string | null;
  private rows: PathVertexRow[][] = [];
  private trees: PathTrees | null = null;
  private request = 0;
  private tracedFor: { pixel: readonly [number, number]; rays: ScreenRays | null } | null = null;
  /** What "show me" asked for, done once the paths are traced. */
  private shown: DebuggerAction | null = null;

  constructor() {
    super();
    this.pixel = null;
    this.settings = null;
    this.scene = null;
    this.screenRays = null;
    this.tracePaths = null;
    this.showFocus = null;
    this.report = null;
    this.paths = null;
    this.path = 0;
    this.vertex = 0;
    this.problem = null;
  }

  override disconnectedCallback(): void {
    super.disconnectedCallback();
    this.request++;
    this.tracedFor = null;
    this.showFocus?.(null);
  }

  protected override willUpdate(changed: PropertyValues<this>): void {
    const pixel = this.pixel;
    const traced = this.tracedFor;
    if (pixel && (!traced || traced.pixel !== pixel || traced.rays !== this.screenRays)) void this.load(pixel);
    if (changed.has('settings') && this.paths && this.settings) this.arrange(this.paths);
  }

  private async load(pixel: readonly [number, number]): Promise<void> {
    this.tracedFor = { pixel, rays: this.screenRays };
    const request = ++this.request;
    if (!this.tracePaths) return;
    try {
      const paths = await this.tracePaths(pixel[0], pixel[1], LAB_PATH_COUNT);
      if (request !== this.request) return;
      this.problem = null;
      this.arrange(paths);
      this.moveTo(Math.min(this.path, paths.paths.length - 1), 0);
      this.applyShown();
    } catch (error) {
      if (request === this.request) this.problem = error instanceof Error ? error.message : String(error);
    }
  }

  private arrange(paths: LabPaths): void {
    const settings = { russianRoulette: this.settings?.russianRoulette ?? false };
    this.paths = paths;
    this.rows = paths.paths.map((path) => pathRows(path, settings));
    this.trees = pathTrees(
      paths,
      this.rows.map((rows) => rows.map((row) => row.throughput)),
    );
  }

  private moveTo(path: number, vertex: number): void {
    if (!this.trees || this.rows.length === 0) return;
    this.path = Math.max(0, Math.min(this.rows.length - 1, path));
    this.vertex = Math.max(0, Math.min(this.rows[this.path].length - 1, vertex));
    this.showFocus?.({ ...pathFocus(this.trees, this.path, this.vertex, this.settings?.bounceSampling), chooseRay: this.chooseRay });
    // As the Whitted debugger does, so that a path level's task can ask for a step.
    const recorded = this.paths?.paths[this.path];
    if (recorded) this.report?.({ type: 'debugger.stepped', step: this.vertex, of: recorded.vertices.length, ray: pathRayOf(recorded, this.vertex) });
  }

  /** A click in the 3D view on a drawn path: the debugger goes to the vertex clicked (path-vertex-pick.ts). */
  private readonly chooseRay = (node: RayNode, at: number): boolean => {
    const choice = this.trees && pathVertexOfRay(this.trees, node, at);
    if (!choice) return false;
    this.moveTo(choice.path, choice.vertex);
    return true;
  };

  /**
   * "Show me" for a task's path-debugger step: goes to the first vertex whose arriving ray
   * matches the solution's (debugger/path-goals.ts findPathVertex), which the debugger then
   * reports as a learner's step; waits for the paths when they are still being traced.
   */
  perform(action: DebuggerAction): void {
    this.shown = action;
    this.applyShown();
  }

  private applyShown(): void {
    const action = this.shown;
    if (!action || !this.paths) return;
    this.shown = null;
    // A term of the Whitted debugger's equation has no path-mode counterpart.
    if (action.type !== 'debugger.stepped') return;
    const found = findPathVertex(this.paths.paths, action.ray);
    if (found) this.moveTo(found.path, found.vertex);
  }

  private move(pathStep: number, vertex: number | 'start' | 'end'): void {
    const path = this.path + pathStep;
    const last = (this.rows[Math.max(0, Math.min(this.rows.length - 1, path))]?.length ?? 1) - 1;
    this.moveTo(path, vertex === 'start' ? 0 : vertex === 'end' ? last : this.vertex + vertex);
  }

  /** Its keys, also when the debugger's card around it has the focus. */
  readonly onKeyDown = (event: KeyboardEvent): void => {
    const move = KEY_MOVES[event.key];
    // The vertex list's own arrows choose in it.
    if (!move || event.altKey || event.ctrlKey || event.metaKey || event.composedPath()[0] instanceof HTMLSelectElement) return;
    event.preventDefault();
    event.stopPropagation();
    this.move(...move);
  };

  protected override updated(): void {
    // The current vertex's row stays in view as the cursor moves.
    this.renderRoot.querySelector('tr.current')?.scrollIntoView({ block: 'nearest' });
    this.dataset.path = this.paths ? String(this.path) : '';
    this.dataset.vertex = this.paths ? String(this.vertex) : '';
    // An option's selected attribute stops counting once the list was used: its value follows the cursor.
    const list = this.renderRoot.querySelector('select');
    if (list) list.value = String(this.vertex);
  }

  override render() {
    if (this.problem) return html`<p role="alert">${msg(str`The paths could not be traced: ${this.problem}`)}</p>`;
    const paths = this.paths;
    const rows = this.rows[this.path]?.map((row) => this.named(row));
    if (!paths || !rows) return html`<p role="status">${msg('Tracing the pixel’s paths…')}</p>`;
    const row = rows[this.vertex];
    const shown = paths.paths.length;
    return html`<div class="controls" role="toolbar" aria-label=${msg('Step along the paths')}>
        <button aria-keyshortcuts="ArrowUp" title=${msg('The previous path (↑)')} ?disabled=${this.path === 0} @click=${() => this.move(-1, 'start')}>▲ ${msg('Path')}</button>
        <strong>${msg(str`Path ${this.path + 1} of ${shown}`)}</strong>
        <button aria-keyshortcuts="ArrowDown" title=${msg('The next path (↓)')} ?disabled=${this.path === shown - 1} @click=${() => this.move(1, 'start')}>${msg('Path')} ▼</button>
        <button aria-keyshortcuts="ArrowLeft" title=${msg('One vertex back (←)')} ?disabled=${this.vertex === 0} @click=${() => this.move(0, -1)}>◀ ${msg('Back')}</button>
        <span>${msg(str`vertex ${this.vertex} of ${rows.length - 1}`)}</span>
        <button aria-keyshortcuts="ArrowRight" title=${msg('One vertex on (→)')} ?disabled=${this.vertex === rows.length - 1} @click=${() => this.move(0, 1)}>${msg('Step')} ▶</button>
        ${this.renderVertexChoice(rows)}
        <span class="muted">${msg('Keys: ← → ↑ ↓ Home End')}</span>
      </div>
      <p role="status" aria-live="polite">${vertexText(row, this.settings?.bounceSampling ?? 'cosine')} ${survivalText(row)}</p>
      ${vertexEstimate(row)}
      <div class="table" tabindex="0" @keydown=${this.onKeyDown}>${pathTable(rows, this.vertex)}</div>
      ${this.renderPixel(paths, rows)}`;
  }

  /** A row with the names the scene list shows ("Back wall", "Achterwand") for its ids. */
  private named(row: PathVertexRow): PathVertexRow {
    const scene = this.scene;
    if (!scene) return row;
    const name = (id: string | null) => (id === null ? null : itemName(scene, id));
    const lightSamples = row.lightSamples.map((sample) => ({ ...sample, lightId: itemName(scene, sample.lightId) }));
    return { ...row, objectId: name(row.objectId), lightId: name(row.lightId), lightSamples };
  }

  /**
   * The vertex chosen from a list (the keyboard's way to what a click on a drawn vertex in
   * the 3D view does): the debugger jumps there, and at a diffuse bounce the lobe is drawn.
   */
  private renderVertexChoice(rows: PathVertexRow[]) {
    return html`<label class="vertex-choice" title=${msg('Or click a vertex of a drawn path in the 3D view.')}
      >${msg('Go to')}
      <select @change=${(event: Event) => this.moveTo(this.path, Number((event.target as HTMLSelectElement).value))}>
        ${rows.map((row, i) => html`<option value=${i} ?selected=${i === this.vertex}>${i} · ${eventName(row.event)}${row.objectId ? ` · ${row.objectId}` : ''}</option>`)}
      </select></label
    >`;
  }

  /** The path's contribution, and the pixel as the mean of all the pixel's paths. */
  private renderPixel(paths: LabPaths, rows: PathVertexRow[]) {
    const done = this.vertex === rows.length - 1;
    const listed = paths.paths.map((path) => colorText(path.contribution)).join(' ');
    return html`<p>
        ${msg('The path’s sum is the Added here column added up.')}
        ${done ? msg(str`This path adds ${colorText(paths.paths[this.path].contribution)} to the pixel.`) : msg('Step to the path’s end to see what it adds to the pixel.')}
        ${
          paths.pathCount === 1
            ? msg(str`The pixel is its one path’s contribution: ${colorText(meanOfPaths(paths.contributions))}.`)
            : msg(str`The pixel is the mean of all ${paths.pathCount} paths’ contributions: ${colorText(meanOfPaths(paths.contributions))}.`)
        }
      </p>
      <p class="muted">
        ${paths.paths.length === 1 ? msg(str`The first path adds: ${listed}.`) : msg(str`The first ${paths.paths.length} paths add: ${listed}.`)}
        ${msg('The 3D view draws them up to this vertex: this path bright, the others dimmed; a click on a drawn vertex goes there. The legend says what the dashes, widths and the lobe mean.')}
      </p>`;
  }
}

customElements.define('rt-path-debugger', RtPathDebugger);

declare global {
  interface HTMLElementTagNameMap {
    'rt-path-debugger': RtPathDebugger;
  }
}
