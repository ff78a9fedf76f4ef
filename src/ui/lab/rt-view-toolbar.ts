import { msg } from '@lit/localize';
import { css, html, nothing, svg, type SVGTemplateResult, type TemplateResult } from 'lit';
import { LocalizedElement } from '../controls/localized-element.ts';
import { DEFAULT_GIZMO, type GizmoOptions } from '../../lab-state/lab-state.ts';
import { GIZMO_MODES, type GizmoMode } from '../../view/gizmo-modes.ts';
import type { ViewCommand } from '../../view/view-commands.ts';
import { GuideHostController } from './guide-host.ts';
import { smallViewToolbarStyles } from './toolbar-small-view.css.ts';
import { guideIds } from '../../quest/lab-controls.ts';

/** How far one button press moves the view (the keys move less, and repeat). */
const ORBIT_STEP_DEG = 15;
const PAN_STEP = 0.1;
const ZOOM_STEP = 1.25;

/**
 * @summary The 3D view's on-screen controls, laid over the view: gizmo mode (move, rotate,
 * scale), local/world axes, snapping, the flight to the ray tracer's camera and help (top);
 * orbit, pan and zoom pads for trackpads and touch screens without a wheel (bottom right).
 *
 * Every button has a visible label or a labelled group (in a small view the camera and help
 * buttons show their icons, their names read out), a tooltip naming its key, and is a
 * real <button>; toggles say their state with aria-pressed and a check mark, not colour alone.
 *
 * `gizmoControls` names the gizmo buttons a level shows (lab-controls.ts: translate, rotate,
 * scale, space, snap); unset, all of them. Every button carries its guide id (gizmo.rotate,
 * view.fly-to-camera, view.help; the pads view.orbit-buttons, view.pan-buttons, view.zoom-buttons).
 *
 * @fires view-command - CustomEvent<ViewCommand>: a button asks the view to do something.
 * @fires view-pads - CustomEvent<boolean>: a small view's pads were unfolded (true) or folded.
 */
export class RtViewToolbar extends LocalizedElement {
  static override properties = {
    gizmo: { attribute: false },
    allowedModes: { attribute: false },
    atCamera: { type: Boolean, attribute: 'at-camera' },
    pixelSelected: { type: Boolean, attribute: 'pixel-selected' },
    gizmoControls: { attribute: false },
    padsOpen: { state: true },
  };

  static override styles = [
    css`
    /* No box of its own: its bars are placed in the 3D view's box (rt-scene-view, the size
       container its small-view rules ask). A box as big as the view, drawn over the WebGL
       canvas, was a layer of its own as big as the view, which the compositor blended anew
       at every frame, a quarter of SwiftShader's frame (figures: docs/benchmark-log.md,
       issue 38). Each bar is now a layer only as big as itself. */
    :host {
      display: contents;
      pointer-events: none;
      font-family: var(--rt-font);
      font-size: 0.8125rem;
      color: var(--rt-text);
      /* A drag that starts on a pad (pressed and held, then moved) would otherwise select the
         page's text, and the selection stayed on across levels. */
      -webkit-user-select: none;
      user-select: none;
    }
    .bar {
      position: absolute;
      display: flex;
      flex-wrap: wrap;
      gap: 8px;
      align-items: flex-start;
    }
    .top {
      top: 8px;
      left: 8px;
      right: 8px;
    }
    /* The camera and help buttons keep to the right, and wrap below when the view is narrow. */
    .top .end {
      margin-left: auto;
    }
    /* Bounded on the left too, so a narrow view (a phone) wraps the pads instead of cutting them off. */
    .bottom-right {
      left: 8px;
      right: 8px;
      bottom: 8px;
      align-items: flex-end;
      justify-content: flex-end;
    }
    .group {
      pointer-events: auto;
      display: flex;
      align-items: center;
      gap: 2px;
      padding: 3px;
      border: 1px solid var(--rt-border);
      border-radius: 10px;
      /* Nearly opaque, with no backdrop blur: a blurred group is blurred again from the 3D
         view under it at every frame the view draws, and on a CPU compositor (SwiftShader)
         the six groups' blur cost 18 ms of a 116 ms frame (docs/benchmark-log.md, ninth round). */
      background: color-mix(in srgb, var(--rt-surface) 94%, transparent);
      box-shadow: 0 2px 8px rgb(0 0 0 / 0.12);
    }
    .pad {
      flex-direction: column;
      gap: 0;
    }
    .pad-grid {
      display: grid;
      grid-template-columns: repeat(3, var(--rt-target));
      grid-template-rows: repeat(3, var(--rt-target));
    }
    .zoom-grid {
      display: grid;
      grid-template-rows: repeat(3, var(--rt-target));
    }
    .caption {
      margin-top: 2px;
      color: var(--rt-muted);
      font-size: 0.75rem;
      line-height: 1.2;
    }
    button {
      box-sizing: border-box;
      min-width: var(--rt-target);
      min-height: var(--rt-target);
      display: inline-flex;
      align-items: center;
      justify-content: center;
      gap: 6px;
      padding: 0 10px;
      border: 1px solid transparent;
      border-radius: 7px;
      background: transparent;
      color: inherit;
      font: inherit;
      cursor: pointer;
      touch-action: manipulation;
    }
    .pad button,
    .zoom-grid button {
      padding: 0;
    }
    button:hover {
      background: color-mix(in srgb, var(--rt-accent) 12%, transparent);
    }
    button[aria-pressed='true'] {
      background: var(--rt-accent);
      color: var(--rt-accent-text);
    }
    button[aria-disabled='true'] {
      opacity: 0.45;
    }
    button:focus-visible {
      outline: 3px solid var(--rt-accent);
      outline-offset: 1px;
    }
    kbd {
      min-width: 1.3em;
      padding: 0 3px;
      border: 1px solid currentColor;
      border-radius: 4px;
      font: inherit;
      font-size: 0.6875rem;
      line-height: 1.3;
      text-align: center;
      opacity: 0.75;
    }
    svg {
      flex: none;
    }
    .check {
      visibility: hidden;
    }
    button[aria-pressed='true'] .check {
      visibility: visible;
    }
    /* A narrow view (a tablet with the panels open) keeps the labels and drops the key hints. */
    @container (max-width: 860px) {
      kbd {
        display: none;
      }
    }
    .centre {
      width: 6px;
      height: 6px;
      margin: auto;
      border-radius: 50%;
      background: var(--rt-muted);
    }
  `,
    smallViewToolbarStyles,
  ];

  /** The store's gizmo options: the pressed mode and toggles. */
  declare gizmo: GizmoOptions;
  /** Modes the selection allows; the others are shown as unavailable (and explain why when pressed). */
  declare allowedModes: readonly GizmoMode[];
  /** Whether the view is at the ray tracer's camera: the fly button then flies back. */
  declare atCamera: boolean;
  /** Whether a pixel is chosen: "Show its rays" is offered then. */
  declare pixelSelected: boolean;
  /** The gizmo buttons on show (undefined: all). */
  declare gizmoControls: readonly string[] | undefined;
  /** In a small view, whether the orbit, pan and zoom pads are unfolded (toolbar-small-view.css.ts). */
  declare private padsOpen: boolean;

  constructor() {
    super();
    this.gizmo = DEFAULT_GIZMO;
    this.allowedModes = GIZMO_MODES;
    this.atCamera = false;
    this.pixelSelected = false;
    this.gizmoControls = undefined;
    this.padsOpen = false;
    new GuideHostController(this);
  }

  private showsGizmo(control: string): boolean {
    return this.gizmoControls === undefined || this.gizmoControls.includes(control);
  }

  override render() {
    const modes = [
      this.modeButton('translate', msg('Move'), 'T', msg('Move the selection with the gizmo (T)')),
      this.modeButton('rotate', msg('Rotate'), 'R', msg('Rotate the selection with the gizmo (R)')),
      this.modeButton(
        'scale',
        msg('Scale', { id: 'gizmo-mode-scale', desc: 'A gizmo mode, beside Move and Rotate: a verb' }),
        'S',
        msg('Scale the selection with the gizmo (S)'),
      ),
    ].filter((button) => button !== nothing);
    const options = [
      this.toggle('space', this.gizmo.space === 'local', msg('Local axes'), 'L', msg("Gizmo along the selection's own axes instead of the world's (L)"), {
        kind: 'toggle-space',
      }),
      this.toggle('snap', this.gizmo.snap, msg('Snap'), 'G', msg('Snap to 0.25 m, 15° and 0.25× steps (G; or hold Shift while dragging)'), {
        kind: 'toggle-snap',
      }),
    ].filter((button) => button !== nothing);
    return html`
      <div class="bar top">
        <div class="start">
          ${modes.length > 0 ? html`<div class="group" role="group" aria-label=${msg('Gizmo mode')}>${modes}</div>` : nothing}
          ${options.length > 0 ? html`<div class="group" role="group" aria-label=${msg('Gizmo options')}>${options}</div>` : nothing}
        </div>
        <div class="group end">
          ${
            this.pixelSelected
              ? html`<button
                data-command="show-pixel-rays"
                data-guide=${guideIds('view.show-pixel-rays')}
                title=${msg("Move the view so that the chosen pixel's whole ray path fits (Z)")}
                @click=${() => this.send({ kind: 'show-pixel-rays' })}
              >
                ${icon(svg`<path d="M3 6V3h3M14 3h3v3M17 14v3h-3M6 17H3v-3" /><circle cx="10" cy="10" r="2.5" />`)}
                <span class="label">${msg('Show its rays')}</span>
              </button>`
              : nothing
          }
          <button
            data-command="fly"
            data-guide=${guideIds('view.fly-to-camera')}
            title=${this.atCamera ? msg('Fly back to where you were (F or Esc)') : msg("Fly to the ray tracer's camera and see what it sees (F)")}
            @click=${() => this.send({ kind: 'fly' })}
          >
            ${icon(this.atCamera ? svg`<path d="M8 4 3 10l5 6M3 10h14" />` : CAMERA)}
            <span class="label">${this.atCamera ? msg('Back to my view') : msg('Camera view')}</span>
          </button>
          <button data-command="help" data-guide=${guideIds('view.help')} title=${msg('All keys and gestures (?)')} @click=${() => this.send({ kind: 'help' })}>
            ${icon(svg`<circle cx="10" cy="10" r="7.5" /><path d="M7.6 7.8a2.5 2.5 0 1 1 3.4 2.3c-.7.3-1 .8-1 1.5v.6" /><circle cx="10" cy="14.6" r=".4" />`)}
            <span class="label">${msg('Help')}</span>
          </button>
        </div>
      </div>
      <div class="bar bottom-right" ?data-open=${this.padsOpen}>
        <div class="pads" id="pads">
        ${this.pad(msg('Orbit'), 'orbit', (dx, dy) => ({ kind: 'orbit', dxDeg: dx * ORBIT_STEP_DEG, dyDeg: dy * ORBIT_STEP_DEG }), {
          left: msg('Orbit left (←)'),
          right: msg('Orbit right (→)'),
          up: msg('Orbit up (↑)'),
          down: msg('Orbit down (↓)'),
        })}
        ${this.pad(msg('Pan'), 'pan', (dx, dy) => ({ kind: 'pan', dx: dx * PAN_STEP, dy: dy * PAN_STEP }), {
          left: msg('Pan left (Shift + ←)'),
          right: msg('Pan right (Shift + →)'),
          up: msg('Pan up (Shift + ↑)'),
          down: msg('Pan down (Shift + ↓)'),
        })}
        <div class="group pad" role="group" aria-label=${msg('Zoom')} data-guide=${guideIds('view.zoom-buttons')}>
          <div class="zoom-grid">
            <button data-command="zoom-in" title=${msg('Zoom in (+)')} aria-label=${msg('Zoom in')} @click=${() => this.send({ kind: 'zoom', factor: ZOOM_STEP })}>
              ${icon(svg`<path d="M10 4v12M4 10h12" />`)}
            </button>
            <span></span>
            <button data-command="zoom-out" title=${msg('Zoom out (−)')} aria-label=${msg('Zoom out')} @click=${() => this.send({ kind: 'zoom', factor: 1 / ZOOM_STEP })}>
              ${icon(svg`<path d="M4 10h12" />`)}
            </button>
          </div>
          <span class="caption" aria-hidden="true">${msg('Zoom')}</span>
        </div>
        </div>
        <button
          class="pads-toggle"
          data-command="view-pads"
          data-guide=${guideIds('view.orbit-buttons', 'view.pan-buttons', 'view.zoom-buttons')}
          aria-expanded=${String(this.padsOpen)}
          aria-controls="pads"
          aria-label=${msg('Orbit, pan, zoom')}
          title=${msg('Show or hide the buttons that orbit, pan and zoom the view')}
          @click=${this.togglePads}
        >
          ${icon(svg`<path d="M10 2.5v15M2.5 10h15M7.5 5 10 2.5 12.5 5M7.5 15l2.5 2.5 2.5-2.5M5 7.5 2.5 10 5 12.5M15 7.5l2.5 2.5-2.5 2.5" />`)}
        </button>
      </div>
    `;
  }

  private modeButton(mode: GizmoMode, label: string, key: string, tooltip: string): TemplateResult | typeof nothing {
    if (!this.showsGizmo(mode)) return nothing;
    const allowed = this.allowedModes.includes(mode);
    const why = allowed ? '' : ` — ${msg('not for this selection')}`;
    return html`<button
      data-command=${mode}
      data-guide=${guideIds(`gizmo.${mode}`)}
      aria-pressed=${String(this.gizmo.mode === mode)}
      aria-disabled=${String(!allowed)}
      title=${tooltip + why}
      @click=${() => this.send({ kind: 'gizmo-mode', mode })}
    >
      ${label} <kbd aria-hidden="true">${key}</kbd>
    </button>`;
  }

  private toggle(control: 'space' | 'snap', on: boolean, label: string, key: string, tooltip: string, command: ViewCommand): TemplateResult | typeof nothing {
    if (!this.showsGizmo(control)) return nothing;
    return html`<button data-command=${command.kind} data-guide=${guideIds(`gizmo.${control}`)} aria-pressed=${String(on)} title=${tooltip} @click=${() => this.send(command)}>
      ${icon(svg`<rect x="3" y="3" width="14" height="14" rx="3" /><path class="check" d="M6 10.5 9 13.5 14.5 7" />`)} ${label}
      <kbd aria-hidden="true">${key}</kbd>
    </button>`;
  }

  /** A 3×3 pad of arrow buttons around a dot, captioned with its name (the visible label). */
  private pad(
    caption: string,
    name: 'orbit' | 'pan',
    command: (dx: number, dy: number) => ViewCommand,
    tooltips: { left: string; right: string; up: string; down: string },
  ): TemplateResult {
    const arrow = (direction: 'left' | 'right' | 'up' | 'down', dx: number, dy: number, path: SVGTemplateResult) =>
      html`<button
        data-command=${`${name}-${direction}`}
        title=${tooltips[direction]}
        aria-label=${tooltips[direction]}
        @click=${() => this.send(command(dx, dy))}
      >
        ${icon(path)}
      </button>`;
    return html`<div class="group pad" role="group" aria-label=${caption} data-guide=${guideIds(`view.${name}-buttons`)}>
      <div class="pad-grid">
        <span></span>${arrow('up', 0, 1, svg`<path d="M5 12l5-5 5 5" />`)}<span></span>
        ${arrow('left', -1, 0, svg`<path d="M12 5l-5 5 5 5" />`)}<span class="centre"></span>${arrow('right', 1, 0, svg`<path d="M8 5l5 5-5 5" />`)}
        <span></span>${arrow('down', 0, -1, svg`<path d="M5 8l5 5 5-5" />`)}<span></span>
      </div>
      <span class="caption" aria-hidden="true">${caption}</span>
    </div>`;
  }

  /** Folds the pads in or out; the lab hears it (`view-pads`), to keep the camera's image from covering them. */
  private readonly togglePads = () => {
    this.padsOpen = !this.padsOpen;
    this.dispatchEvent(new CustomEvent<boolean>('view-pads', { detail: this.padsOpen, bubbles: true, composed: true }));
  };

  private send(command: ViewCommand): void {
    this.dispatchEvent(new CustomEvent<ViewCommand>('view-command', { detail: command, bubbles: true, composed: true }));
  }
}

const CAMERA = svg`<rect x="2.5" y="6" width="10" height="8.5" rx="1.5" /><path d="M12.5 9l5-2.5v7.5l-5-2.5" />`;

function icon(body: SVGTemplateResult): TemplateResult {
  return html`<svg viewBox="0 0 20 20" width="18" height="18" aria-hidden="true" fill="none" stroke="currentColor" stroke-width="1.7" stroke-linecap="round" stroke-linejoin="round">${body}</svg>`;
}

customElements.define('rt-view-toolbar', RtViewToolbar);

declare global {
  interface HTMLElementTagNameMap {
    'rt-view-toolbar': RtViewToolbar;
  }
  interface HTMLElementEventMap {
    'view-command': CustomEvent<ViewCommand>;
  }
}
