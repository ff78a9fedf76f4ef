import { msg, str } from '@lit/localize';
import { html, nothing } from 'lit';
import { ifDefined } from 'lit/directives/if-defined.js';
import type { LabAction } from '../../../lab-state/lab-action.ts';
import type { BounceSampling, Camera, ImageEncoding, Integrator, LightType, RenderSettings, SamplePattern, TimePattern } from '../../../scene/scene.ts';
import { LIMITS } from '../../../scene/scene-limits.ts';
import { effectiveFocusDistance, focusDistanceTo } from '../../../scene/camera-focus.ts';
import { shownName } from '../scene-names.ts';
import { apertureSpec, focusDistanceSpec, lensSamplesHint, lensSamplesSpec, timeSamplesSpec } from './distribution-specs.ts';
import {
  bounceSamplingOptions,
  bounceSamplingText,
  exposureSpec,
  integratorOptions,
  integratorText,
  lightSamplingText,
  maxBouncesText,
  pathSamplesHint,
  pathSamplesSpec,
  russianRouletteText,
} from './path-specs.ts';
import { StorePanel, type ControlPart, type ControlText } from './store-panel.ts';

const LIGHT_TYPES: LightType[] = ['point', 'spot', 'area'];

/**
 * @summary The ray tracer's settings (the original lab's ray tracer panel): shadows,
 * recursion depth, background, a switch per light type, dithering and the image's 8-bit
 * encoding (none, linear, sRGB: src/tracer/quantize.ts); supersampling with its
 * pattern and "show sample points"; the camera's screen of pixels and field of view; and
 * the lens and shutter (aperture, focus distance, lens and time samples, the time pattern);
 * and the size of the rendered image.
 *
 * Edits are `settings.changed`, `camera.changed` and (sample points) `rays.changed`
 * actions on `store`; a refused edit's reason is shown next to its control.
 */
export class RtTracerPanel extends StorePanel<'tracer'> {
  protected readonly controlPanel = 'tracer';

  override render() {
    if (!this.state) return html``;
    const { settings, camera } = this.state.scene;
    const set = (changes: Partial<RenderSettings>): LabAction => ({ type: 'settings.changed', changes });
    const cam = (changes: Partial<Camera>): LabAction => ({ type: 'camera.changed', changes });
    const s = settings.supersampling;
    return html`
      ${this.section(msg('Ray tracer'), 'tracer', [
        this.switch(
          { name: 'shadows', label: msg('Shadows'), tooltip: msg('Send a shadow ray to each light; when off, every light reaches every point.') },
          settings.shadows,
          (shadows) => set({ shadows }),
        ),
        this.slider(
          {
            // Path mode counts the same setting as bounces (docs/path-tracing.md).
            ...(settings.integrator === 'path'
              ? maxBouncesText()
              : {
                  name: 'maxDepth',
                  label: msg('Recursion depth'),
                  tooltip: msg('How many times a ray may reflect or refract; at 0 the rays from the camera and their shadow rays are still traced.'),
                }),
            min: LIMITS.maxDepth[0],
            max: LIMITS.maxDepth[1],
            step: 1,
            whole: true,
          },
          settings.maxDepth,
          (maxDepth) => set({ maxDepth }),
        ),
        this.color(
          { name: 'background', label: msg('Background'), tooltip: msg('The colour of a ray that hits nothing.') },
          settings.background,
          (background) => set({ background }),
        ),
        ...LIGHT_TYPES.map((type) =>
          this.switch(lightTypeSwitch(type), settings.lightTypes[type], (on) => set({ lightTypes: { ...settings.lightTypes, [type]: on } })),
        ),
        this.switch(
          {
            name: 'dithering',
            label: msg('Dithering'),
            tooltip: msg('Add a fine pattern before rounding to 8-bit colours, which hides the bands in smooth gradients.'),
          },
          settings.dithering,
          (dithering) => set({ dithering }),
        ),
        this.choice<ImageEncoding>(
          {
            name: 'encoding',
            label: msg('Encoding'),
            tooltip: msg('How each pixel’s light becomes a whole number from 0 to 255 (8 bits) in the rendered image.'),
          },
          [
            {
              value: 'none',
              label: msg('None'),
              tooltip: msg(
                'The colour c is written as c × 255 and the screen reads that number as its own value, so you see less light than c (no gamma, as in the Virtual Ray Tracer).',
              ),
            },
            {
              value: 'linear',
              label: msg('Linear'),
              tooltip: msg('The light is stored in 256 equal steps and shown as that light: few steps for the dark tones.'),
            },
            {
              value: 'srgb',
              label: msg('sRGB'),
              tooltip: msg('The light is sRGB-encoded before it is rounded, as in photos and PNG files: many steps for the dark tones.'),
            },
          ],
          settings.encoding,
          (encoding) => set({ encoding }),
        ),
      ])}
      ${this.section(msg('Path tracing'), 'tracer-path', this.pathControls(settings))}
      ${this.section(msg('Anti-aliasing'), 'tracer-supersampling', [
        this.slider(
          {
            name: 'supersampling',
            label: msg('Supersampling (s)'),
            tooltip: msg('s × s rays per pixel, averaged: smoother edges, s² times the work. Type up to 8.'),
            min: LIMITS.supersampling[0],
            max: 4,
            step: 1,
            inputMax: LIMITS.supersampling[1],
            whole: true,
          },
          s,
          (supersampling) => set({ supersampling }),
          s === 1 ? msg('1 ray per pixel') : msg(str`${s} × ${s} = ${s * s} rays per pixel`),
        ),
        this.choice<SamplePattern>(
          { name: 'samplePattern', label: msg('Pattern'), tooltip: msg('Where the rays go inside each pixel.') },
          [
            { value: 'grid', label: msg('Grid'), tooltip: msg('A regular grid: even, but patterns can show.') },
            { value: 'jittered', label: msg('Jittered'), tooltip: msg('One random spot in each cell of the grid.') },
            { value: 'random', label: msg('Random'), tooltip: msg('Anywhere in the pixel: can clump and leave gaps.') },
          ],
          settings.samplePattern,
          (samplePattern) => set({ samplePattern }),
        ),
        this.switch(
          { name: 'showSamplePoints', label: msg('Show sample points'), tooltip: msg('Draw where each pixel’s rays go on the camera’s screen.') },
          this.state.rays.showSamplePoints,
          (showSamplePoints) => ({ type: 'rays.changed', changes: { showSamplePoints } }),
        ),
      ])}
      ${this.section(msg('Camera'), 'tracer-camera', [
        ...([0, 1] as const).map((axis) =>
          this.slider(
            {
              ...pixelsText(axis),
              min: LIMITS.pixels[0],
              max: 16,
              step: 1,
              inputMax: LIMITS.pixels[1],
              whole: true,
            },
            camera.pixels[axis],
            (n) => cam({ pixels: axis === 0 ? [n, camera.pixels[1]] : [camera.pixels[0], n] }),
          ),
        ),
        this.slider(
          {
            name: 'fov',
            label: msg('Field of view'),
            tooltip: msg('How wide the camera sees, top to bottom, in degrees: smaller zooms in.'),
            min: LIMITS.fov[0],
            max: LIMITS.fov[1],
            step: 1,
            unit: '°',
          },
          camera.fov,
          (fov) => cam({ fov }),
        ),
      ])}
      ${this.section(msg('Lens and shutter'), 'tracer-lens', this.lensControls())}
      ${this.section(msg('Rendered image'), 'tracer-image', [
        this.vector<[number, number]>(
          {
            name: 'imageSize',
            label: msg('Image size'),
            tooltip: msg('Width and height in pixels of the image the render window makes.'),
            axes: [msg('width'), msg('height')],
            min: LIMITS.imageSize[0],
            max: LIMITS.imageSize[1],
            step: 1,
            unit: 'px',
            whole: true,
            limitReason: msg(
              str`the tracer renders at most ${LIMITS.imageSize[1]} pixels per side, so that the image fits in the browser's memory (${LIMITS.imageSize[1]} × ${LIMITS.imageSize[1]} is already 16 million pixels).`,
            ),
          },
          settings.imageSize,
          (imageSize) => set({ imageSize }),
        ),
      ])}
    `;
  }

  /** Path mode (spec path-tracing §1): the estimator, N paths per pixel, the bounce and light sampling, Russian roulette, the exposure. */
  private pathControls(settings: RenderSettings): ControlPart[] {
    const set = (changes: Partial<RenderSettings>): LabAction => ({ type: 'settings.changed', changes });
    return [
      this.choice<Integrator>(integratorText(), integratorOptions(), settings.integrator, (integrator) => set({ integrator })),
      this.slider(pathSamplesSpec(), settings.pathSamples, (pathSamples) => set({ pathSamples }), pathSamplesHint(settings.pathSamples)),
      this.choice<BounceSampling>(bounceSamplingText(), bounceSamplingOptions(), settings.bounceSampling, (bounceSampling) => set({ bounceSampling })),
      this.switch(lightSamplingText(), settings.lightSampling, (lightSampling) => set({ lightSampling })),
      this.switch(russianRouletteText(), settings.russianRoulette, (russianRoulette) => set({ russianRoulette })),
      this.slider(exposureSpec(), settings.exposure, (exposure) => set({ exposure })),
    ];
  }

  /** Depth of field and motion blur: aperture, focus distance (with "focus on the selected object"), lens and time samples, and when the time samples fall. */
  private lensControls(): ControlPart[] {
    if (!this.state) return [];
    const { camera, settings, objects } = this.state.scene;
    const cam = (changes: Partial<Camera>): LabAction => ({ type: 'camera.changed', changes });
    const selection = this.state.selection;
    const selected = selection?.kind === 'object' ? objects.find((o) => o.id === selection.id) : undefined;
    const n = camera.lensSamples;
    const k = settings.timeSamples;
    return [
      this.slider(apertureSpec(), camera.aperture, (aperture) => cam({ aperture })),
      this.slider(focusDistanceSpec(), effectiveFocusDistance(camera), (focusDistance) => cam({ focusDistance })),
      this.shows('focusOnSelected')
        ? html`<button
              type="button"
              data-guide=${ifDefined(this.guideOf('focusOnSelected'))}
              title=${msg('Put the plane in focus through the selected object’s centre.')}
              ?disabled=${!selected}
              @click=${() => selected && this.send('focusOnSelected', cam({ focusDistance: focusDistanceTo(camera, selected.position) }))}
            >
              ${selected ? msg(str`Focus on ${shownName(selected.name, selected.id)}`) : msg('Focus on the selected object')}
            </button>
            ${this.errorLine('focusOnSelected')}`
        : nothing,
      this.slider(lensSamplesSpec(camera.aperture === 0), n, (lensSamples) => cam({ lensSamples }), lensSamplesHint(n, camera.aperture)),
      this.slider(
        timeSamplesSpec(),
        k,
        (timeSamples) => ({ type: 'settings.changed', changes: { timeSamples } }),
        k === 1 ? msg('The shutter sees one moment') : msg(str`${k} moments per sample`),
      ),
      // The pixel's pattern choice, in time (shutter-times.ts): fixed moments give copies, moments per pixel give grain.
      this.choice<TimePattern>(
        {
          name: 'timePattern',
          label: msg('Time pattern'),
          tooltip: msg('When in the open shutter each pixel’s rays are sent (with more than 1 time sample).'),
        },
        [
          { value: 'grid', label: msg('Grid'), tooltip: msg('The same evenly spaced moments for every pixel: a moving object shows as separate copies.') },
          {
            value: 'jittered',
            label: msg('Jittered'),
            tooltip: msg('One random moment in each equal part of the open shutter, new for every pixel: a grainy streak instead of copies.'),
          },
          {
            value: 'random',
            label: msg('Random'),
            tooltip: msg('Moments anywhere in the open shutter, new for every pixel: they can clump, so the streak is grainier.'),
          },
        ],
        settings.timePattern,
        (timePattern) => ({ type: 'settings.changed', changes: { timePattern } }),
      ),
    ];
  }
}

/** The camera screen's columns (axis 0) and rows (axis 1). The lab's slider stops at 16 per side, as VRT's did; typing goes to the schema's 64. */
function pixelsText(axis: 0 | 1): ControlText<'pixels.columns' | 'pixels.rows'> {
  return axis === 0
    ? { name: 'pixels.columns', label: msg('Pixel columns'), tooltip: msg('Columns of the camera’s small screen whose rays are drawn. Type up to 64.') }
    : { name: 'pixels.rows', label: msg('Pixel rows'), tooltip: msg('Rows of the camera’s small screen whose rays are drawn. Type up to 64.') };
}

/** Whole phrases per type, so that translations need not build plurals. */
function lightTypeSwitch(type: LightType): ControlText<`lightTypes.${LightType}`> {
  const name = `lightTypes.${type}` as const;
  switch (type) {
    case 'point':
      return { name, label: msg('Point lights'), tooltip: msg('Switch all point lights on or off at once (off: they light nothing).') };
    case 'spot':
      return { name, label: msg('Spot lights'), tooltip: msg('Switch all spot lights on or off at once (off: they light nothing).') };
    case 'area':
      return { name, label: msg('Area lights'), tooltip: msg('Switch all area lights on or off at once (off: they light nothing).') };
  }
}

customElements.define('rt-tracer-panel', RtTracerPanel);

declare global {
  interface HTMLElementTagNameMap {
    'rt-tracer-panel': RtTracerPanel;
  }
}
