import { msg, str } from '@lit/localize';
import { html, nothing, type PropertyValues } from 'lit';
import { equationAt, pixelAverage } from '../../../debugger/debug-equation.ts';
import { debugProgram, moveCursor, raysShownAt, type DebugProgram, type DebugStep } from '../../../debugger/debug-steps.ts';
import { debuggerRayOf, findStep, findTerm } from '../../../debugger/debug-goals.ts';
import { isDark, whyDark } from '../../../debugger/why-dark.ts';
import type { DebuggerAction, LabAction } from '../../../lab-state/lab-action.ts';
import { LAB_CONTROLS } from '../../../quest/lab-controls.ts';
import type { ScreenRays } from '../../../render/screen-rays.ts';
import type { PixelTrace, RayNode } from '../../../tracer/ray-tree.ts';
import { PLAIN_QUANTIZATION } from '../../../tracer/quantize.ts';
import type { RayFocus } from '../../../view/ray-focus.ts';
import { StorePanel } from '../panels/store-panel.ts';
import { darkReasonText, stepText } from './debugger-text.ts';
import { debuggerStyles } from './debugger-styles.ts';
import type { PixelSum, TermClickDetail } from './rt-debug-equation.ts';
import './rt-debug-code.ts';
import './rt-debug-equation.ts';
import './rt-debug-tree.ts';
import './rt-path-debugger.ts';
import type { LabPaths } from '../../../tracer/lab-paths.ts';

/** Milliseconds between steps while playing: time to see a ray grow (about 1 s at the default speed) and read the line. */
export const PLAY_INTERVAL_MS = 1100;

/** Keys → the cursor's moves (Space plays and pauses). */
const KEY_MOVES: Readonly<Record<string, 'step' | 'back' | 'reset' | 'end'>> = {
  ArrowRight: 'step',
  ArrowLeft: 'back',
  Home: 'reset',
  End: 'end',
};

/**
 * @summary The ray debugger (ray-debugger spec §2): steps through the selected pixel's rays
 * in the order the tracer made them, one ray highlighted in the 3D view (the others dimmed),
 * the pseudocode's current line lit, the pixel's samples and rays as a tree with each one's
 * share and the pixel's running sum, the current hit's colour written out as its terms,
 * growing step by step (a clicked term highlights its ray), the pixel as the sum of its rays
 * next to the image's pixel, and, on a dark pixel, "why is it dark here?" in words.
 *
 * Keyboard: with focus in the debugger, → steps, ← steps back, Space plays or pauses, Home
 * goes to the start and End to the end; every step is announced (a live region).
 *
 * `tracePixel`: traces a pixel with its shading terms (the lab's services); `screenRays`: the
 * camera's latest screen (a new one re-traces the pixel); `showFocus`: draws the focus in 3D.
 * Reports `debugger.stepped` and `debugger.term-clicked` to the store, and `panel.opened`.
 * Carries `data-step`, `data-line` and `data-ray` (the highlighted ray's kind) for tests.
 */
export class RtRayDebugger extends StorePanel<'debugger'> {
  protected readonly controlPanel = 'debugger';

  static override properties = {
    ...StorePanel.properties,
    tracePixel: { attribute: false },
    tracePaths: { attribute: false },
    screenRays: { attribute: false },
    showFocus: { attribute: false },
    open: { type: Boolean, reflect: true },
    program: { state: true },
    index: { state: true },
    playing: { state: true },
    pinned: { state: true },
    problem: { state: true },
  };

  static override styles = [StorePanel.styles, debuggerStyles];

  declare tracePixel: ((x: number, y: number) => Promise<PixelTrace>) | null;
  /** In path mode the debugger steps through the pixel's sample paths instead (rt-path-debugger.ts). */
  declare tracePaths: ((x: number, y: number, keep: number) => Promise<LabPaths>) | null;
  declare screenRays: ScreenRays | null;
  declare showFocus: ((focus: RayFocus | null) => void) | null;
  declare open: boolean;
  declare private program: DebugProgram | null;
  declare private index: number;
  declare private playing: boolean;
  /** A clicked term: its id, and the ray highlighted instead of the step's. */
  declare private pinned: { id: string; ray: RayNode } | null;
  declare private problem: string | null;
  private timer: ReturnType<typeof setInterval> | null = null;
  /** Which trace request is the latest (older answers are dropped). */
  private request = 0;
  private tracedFor: { pixel: readonly [number, number]; rays: ScreenRays | null } | null = null;
  /** What "show me" asked for, done once the pixel is traced. */
  private shown: DebuggerAction | null = null;

  constructor() {
    super();
    this.tracePixel = null;
    this.tracePaths = null;
    this.screenRays = null;
    this.showFocus = null;
    this.open = false;
    this.program = null;
    this.index = 0;
    this.playing = false;
    this.pinned = null;
    this.problem = null;
  }

  override disconnectedCallback(): void {
    super.disconnectedCallback();
    this.stopPlaying();
    this.showFocus?.(null);
  }

  protected override willUpdate(changed: PropertyValues<this>): void {
    super.willUpdate(changed);
    const pixel = this.state?.selectedPixel ?? null;
    if (!this.open || !pixel || this.pathMode) {
      if (this.program) this.leave();
      return;
    }
    const traced = this.tracedFor;
    if (!traced || traced.pixel !== pixel || traced.rays !== this.screenRays) void this.load(pixel);
  }

  /** Traces the pixel with its terms; the same pixel again (a changed scene) keeps the cursor where it can. */
  private async load(pixel: readonly [number, number]): Promise<void> {
    const samePixel = this.tracedFor?.pixel[0] === pixel[0] && this.tracedFor?.pixel[1] === pixel[1];
    this.tracedFor = { pixel, rays: this.screenRays };
    const request = ++this.request;
    if (!this.tracePixel || !this.screenRays) return;
    try {
      const trace = await this.tracePixel(pixel[0], pixel[1]);
      if (request !== this.request || !this.state) return;
      const program = debugProgram(trace, this.state.scene);
      this.program = program;
      this.problem = null;
      this.moveTo(samePixel ? Math.min(this.index, program.steps.length - 1) : 0);
      this.applyShown();
    } catch (error) {
      if (request === this.request) this.problem = error instanceof Error ? error.message : String(error);
    }
  }

  private leave(): void {
    this.request++;
    this.stopPlaying();
    this.program = null;
    this.tracedFor = null;
    this.pinned = null;
    this.showFocus?.(null);
  }

  private get pathMode(): boolean {
    return this.state?.scene.settings.integrator === 'path';
  }

  private get step(): DebugStep | null {
    return this.program?.steps[this.index] ?? null;
  }

  /** Moves the cursor, draws its rays and tells the quest engine which ray it reached. */
  private moveTo(index: number, pinned: RtRayDebugger['pinned'] = null): void {
    const program = this.program;
    if (!program) return;
    this.index = index;
    this.pinned = pinned;
    const step = program.steps[index];
    const grows = !pinned && (step.kind === 'cast' || step.kind === 'light');
    // A clicked term's ray is drawn even before the cursor reaches it.
    const shown = new Set(raysShownAt(program, index));
    if (pinned) shown.add(pinned.ray);
    this.showFocus?.({ trace: program.trace, shown, highlighted: pinned?.ray ?? step.ray, grow: grows });
    if (pinned) return;
    this.report({ type: 'debugger.stepped', step: index, of: program.steps.length, ray: debuggerRayOf(step) });
  }

  /**
   * "Show me" performs a debugger action visibly: the debugger opens on the selected pixel and
   * moves to the first step that reaches the action's ray (in path mode the path debugger goes
   * to its vertex), or clicks the action's term at the first hit that has it (reported as a learner's).
   */
  perform(action: DebuggerAction): void {
    if (this.pathMode) {
      if (!this.open) this.toggleOpen(true);
      void this.updateComplete.then(() => this.renderRoot.querySelector('rt-path-debugger')?.perform(action));
      return;
    }
    this.shown = action;
    if (!this.open) this.toggleOpen(true);
    else this.applyShown();
  }

  private applyShown(): void {
    const action = this.shown;
    const program = this.program;
    const scene = this.state?.scene;
    if (!action || !program || !scene) return;
    this.shown = null;
    if (action.type === 'debugger.stepped') {
      // The solution's own ray, else (another pixel, a changed scene) the first ray of its kind.
      let index = action.ray ? findStep(program, action.ray) : program.steps.length - 1;
      if (index < 0 && action.ray) index = findStep(program, { type: action.ray.type });
      if (index >= 0) this.moveTo(index);
      return;
    }
    const found = findTerm(program, scene, action.term, action.lightId);
    if (!found?.term.ray) return;
    this.moveTo(found.step);
    this.moveTo(found.step, { id: found.term.id, ray: found.term.ray });
    this.report({ type: 'debugger.term-clicked', term: found.term.kind, lightId: found.term.lightId });
  }

  private report(action: LabAction): void {
    this.send('debugger', action);
  }

  private move(move: 'step' | 'back' | 'reset' | 'end'): void {
    if (!this.program) return;
    if (move !== 'step') this.stopPlaying();
    this.moveTo(moveCursor(this.program, this.index, move));
  }

  private togglePlay(): void {
    if (this.playing) {
      this.stopPlaying();
      return;
    }
    const program = this.program;
    if (!program) return;
    if (this.index >= program.steps.length - 1) this.moveTo(0);
    this.playing = true;
    this.timer = setInterval(() => {
      if (!this.program || this.index >= this.program.steps.length - 1) this.stopPlaying();
      else this.move('step');
    }, PLAY_INTERVAL_MS);
  }

  private stopPlaying(): void {
    if (this.timer !== null) clearInterval(this.timer);
    this.timer = null;
    this.playing = false;
  }

  private toggleOpen(open: boolean): void {
    this.open = open;
    if (open) {
      this.report({ type: 'panel.opened', panel: 'debugger' });
      // Keyboard users land in the debugger, where its keys work.
      void this.updateComplete.then(() => this.renderRoot.querySelector<HTMLElement>('.card')?.focus());
    } else this.leave();
  }

  private onKeyDown(event: KeyboardEvent): void {
    if (this.pathMode) return this.renderRoot.querySelector('rt-path-debugger')?.onKeyDown(event);
    const target = event.composedPath()[0];
    const onButton = target instanceof HTMLButtonElement;
    if (event.key === ' ' && !onButton) {
      event.preventDefault();
      this.togglePlay();
      return;
    }
    const move = KEY_MOVES[event.key];
    if (!move || event.altKey || event.ctrlKey || event.metaKey) return;
    event.preventDefault();
    this.move(move);
    void this.keepFocus();
  }

  /** A step can remove the focused control (a term of the last hit's equation): focus then stays in the debugger. */
  private async keepFocus(): Promise<void> {
    await this.updateComplete;
    await this.renderRoot.querySelector('rt-debug-equation')?.updateComplete;
    if (!this.matches(':focus-within')) this.renderRoot.querySelector<HTMLElement>('.card')?.focus();
  }

  private onTermClick(event: CustomEvent<TermClickDetail>): void {
    const term = event.detail;
    if (!term.ray) return;
    this.stopPlaying();
    this.moveTo(this.index, { id: term.id, ray: term.ray });
    this.report({ type: 'debugger.term-clicked', term: term.kind, lightId: term.lightId });
  }

  private useMiddlePixel(): void {
    const [columns, rows] = this.state?.scene.camera.pixels ?? [1, 1];
    this.send('pixel', { type: 'pixel.selected', pixel: [Math.floor(columns / 2), Math.floor(rows / 2)] });
  }

  /** The step, its line and the highlighted ray's kind, readable from outside (browser tests, tools). */
  protected override updated(): void {
    const step = this.open ? this.step : null;
    const highlighted = this.pinned?.ray ?? step?.ray ?? null;
    this.dataset.step = step ? String(this.index) : '';
    this.dataset.line = step?.line ?? '';
    this.dataset.ray = highlighted?.type ?? '';
  }

  override render() {
    if (!this.open) {
      // Closed, its button stands for every control of the debugger (the hint ring goes there first).
      const guides = LAB_CONTROLS.debugger.filter((id) => !this.shownControls || this.shownControls.includes(id)).map((id) => `debugger.${id}`);
      return html`<button class="opener" data-guide=${guides.join(' ')} title=${msg('Step through one pixel’s rays, as a debugger steps through code')} @click=${() => this.toggleOpen(true)}>
        ${msg('Debug a pixel')}
      </button>`;
    }
    const pixel = this.state?.selectedPixel ?? null;
    return html`<section class="card" role="region" aria-label=${msg('Ray debugger')} tabindex="-1" @keydown=${this.onKeyDown}>
      <header>
        <h2 data-guide=${this.guideOf('open') ?? nothing}>${msg('Ray debugger')}</h2>
        <span class="where">${pixel ? msg(str`Pixel ${pixel[0]}, ${pixel[1]}`) : ''}${this.program ? ` · ${msg(str`step ${this.index + 1} of ${this.program.steps.length}`)}` : ''}</span>
        ${pixel && this.program ? this.renderControls(this.program) : nothing}
        <button class="close" data-guide=${this.guideOf('close') ?? nothing} title=${msg('Close the debugger and show every ray again')} @click=${() => this.toggleOpen(false)}>
          ${msg('Close')}
        </button>
      </header>
      ${pixel ? (this.pathMode ? this.renderPaths(pixel) : this.renderProgram()) : this.renderNoPixel()}
    </section>`;
  }

  private renderNoPixel() {
    return html`<div class="ask">
      <p>${msg('Choose a pixel first: click one on the camera’s screen in the 3D view or in the image preview.')}</p>
      <button @click=${this.useMiddlePixel}>${msg('Use the middle pixel')}</button>
    </div>`;
  }

  private renderPaths(pixel: readonly [number, number]) {
    const settings = this.state?.scene.settings ?? null;
    return html`<rt-path-debugger .pixel=${pixel} .settings=${settings} .scene=${this.state?.scene ?? null} .screenRays=${this.screenRays} .tracePaths=${this.tracePaths} .showFocus=${this.showFocus} .report=${(action: LabAction) => this.report(action)}></rt-path-debugger>`;
  }

  private renderProgram() {
    const program = this.program;
    const step = this.step;
    const scene = this.state?.scene ?? null;
    if (this.problem) return html`<p class="problem" role="alert">${msg(str`The pixel could not be traced: ${this.problem}`)}</p>`;
    if (!program || !step || !scene) return html`<p role="status">${msg('Tracing the pixel…')}</p>`;
    return html`
      <p class="now" role="status" aria-live="polite">${stepText(step, scene)}</p>
      <div class="columns">
        <!-- Focusable: its lines scroll in a short dock, and a keyboard must be able to scroll them too (WCAG 2.1.1). -->
        <rt-debug-code tabindex="0" data-guide=${this.guideOf('code') ?? nothing} .line=${step.line}></rt-debug-code>
        <rt-debug-tree .program=${program} .index=${this.index} .scene=${scene} .quantization=${scene.settings}></rt-debug-tree>
        <div class="right">
          <rt-debug-equation
            data-guide=${[this.guideOf('equation'), step.kind === 'average' ? this.guideOf('pixel') : undefined].filter(Boolean).join(' ')}
            .scene=${scene}
            .equation=${equationAt(program, this.index, scene)}
            .average=${step.kind === 'average' ? this.pixelSum(program) : null}
            .chosen=${this.pinned?.id ?? null}
            @term-click=${this.onTermClick}
          ></rt-debug-equation>
          ${this.renderWhyDark(step, program)}
        </div>
      </div>
    `;
  }

  private renderControls(program: DebugProgram) {
    const last = program.steps.length - 1;
    return html`<div class="controls" role="toolbar" aria-label=${msg('Step through the rays')}>
        <button data-guide=${this.guideOf('reset') ?? nothing} aria-keyshortcuts="Home" title=${msg('Back to the first step (Home)')} ?disabled=${this.index === 0} @click=${() => this.move('reset')}>${msg('Reset')}</button>
        <button data-guide=${this.guideOf('back') ?? nothing} aria-keyshortcuts="ArrowLeft" title=${msg('One step back (←)')} ?disabled=${this.index === 0} @click=${() => this.move('back')}>◀ ${msg('Back')}</button>
        <button data-guide=${this.guideOf('play') ?? nothing} aria-keyshortcuts="Space" aria-pressed=${this.playing ? 'true' : 'false'} title=${msg('Step on by itself (Space)')} @click=${this.togglePlay}>
          ${this.playing ? msg('Pause') : msg('Play')}
        </button>
        <button data-guide=${this.guideOf('step') ?? nothing} aria-keyshortcuts="ArrowRight" title=${msg('One step on (→)')} ?disabled=${this.index === last} @click=${() => this.move('step')}>${msg('Step')} ▶</button>
        <span class="keys">${msg('Keys: → ← Space Home End')}</span>
      </div>`;
  }

  private pixelSum(program: DebugProgram): PixelSum {
    const [x, y] = program.trace.pixel;
    const screen = this.screenRays;
    const image = screen && x < screen.columns && y < screen.rows ? (screen.traces[y * screen.columns + x]?.color ?? null) : null;
    return { ...pixelAverage(program), image, pixel: [x, y], quantization: this.state?.scene.settings ?? PLAIN_QUANTIZATION };
  }

  /** "Why is it dark here?", only on a dark pixel: the reasons of the hit the step is at (or of its sample's first hit). */
  private renderWhyDark(step: DebugStep, program: DebugProgram) {
    const scene = this.state?.scene;
    if (!scene || !isDark(program.trace.color)) return nothing;
    const missed = step.ray && !step.ray.hit && (step.kind === 'cast' || step.kind === 'return') ? step.ray : null;
    const root = program.trace.rays[step.sample];
    const firstRay = root?.children.length && root.children.every((child) => child.type === 'primary') ? root.children[0] : root;
    const subject = missed ?? step.hit ?? firstRay;
    const reasons = subject ? whyDark(subject, scene) : [];
    return html`<div class="why" data-guide=${this.guideOf('why-dark') ?? nothing}>
      <h3>${msg('Why is it dark here?')}</h3>
      ${
        reasons.length === 0
          ? html`<p>${msg('No light is cut off at this point: it is as dark as its terms add up to (its colour C, kd, and the lights’ I and A).')}</p>`
          : html`<ul>${reasons.map((reason) => html`<li>${darkReasonText(reason, scene)}</li>`)}</ul>`
      }
    </div>`;
  }
}

customElements.define('rt-ray-debugger', RtRayDebugger);

declare global {
  interface HTMLElementTagNameMap {
    'rt-ray-debugger': RtRayDebugger;
  }
}
