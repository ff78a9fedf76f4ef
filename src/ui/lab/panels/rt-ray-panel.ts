import { msg } from '@lit/localize';
import { html, nothing } from 'lit';
import { ifDefined } from 'lit/directives/if-defined.js';
import type { LabAction } from '../../../lab-state/lab-action.ts';
import type { RayViewOptions } from '../../../lab-state/lab-state.ts';
import { NEGLIGIBLE_THRESHOLD } from './negligible-threshold.ts';
import './rt-ray-legend.ts';
import { StorePanel } from './store-panel.ts';

/** Radii are stored in metres and shown in centimetres: rays are 1 cm, not 0.01 m, to a student. */
const CM_PER_M = 100;

/** Ray radius in cm: thinner than 1 mm vanishes at lab distances, 10 cm rays hide the scene. */
const RADIUS_CM = { min: 0.1, max: 10, step: 0.1 } as const;

/**
 * Growth speed in m/s. The slider covers a comfortable range for watching a tree grow
 * (a 10 m missed ray takes 20 s at the slowest, 0.5 s at the fastest); typing allows up to
 * 100 m/s for "pixel by pixel" on a big screen, which otherwise takes minutes.
 */
const SPEED = { min: 0.5, max: 20, step: 0.5, inputMax: 100 } as const;

/**
 * @summary The ray visualization options of the original lab's ray panel: show rays, hide
 * rays that hit nothing, hide negligible rays below a threshold, transparency, the radius
 * (fixed, or from each ray's contribution between a minimum and a maximum; min > max makes
 * small contributions thick), colour by contribution, the colour-blind-safe palette with
 * the legend, and the growth animation (speed, pixel by pixel, loop).
 *
 * ("Show sample points" is in the ray tracer panel, next to supersampling.) Every slider
 * shows its value, takes a typed number and clamps one out of range with a visible note.
 * Each change is a `rays.changed` action on `store`.
 */
export class RtRayPanel extends StorePanel<'rays'> {
  protected readonly controlPanel = 'rays';

  override render() {
    const rays = this.state?.rays;
    if (!rays) return html``;
    const set = (changes: Partial<RayViewOptions>): LabAction => ({ type: 'rays.changed', changes });
    return html`
      ${this.section(msg('Rays'), 'rays', [
        this.switch(
          { name: 'showRays', label: msg('Show rays'), tooltip: msg('Draw the rays of the camera’s pixels in the 3D view.') },
          rays.showRays,
          (showRays) => set({ showRays }),
        ),
        this.switch(
          {
            name: 'hideNoHit',
            label: msg('Hide rays that hit nothing'),
            tooltip: msg('Hide the rays that fly off into the background (drawn red, 10 m long).'),
          },
          rays.hideNoHit,
          (hideNoHit) => set({ hideNoHit }),
        ),
        this.switch(
          {
            name: 'hideNegligible',
            label: msg('Hide negligible rays'),
            tooltip: msg('Hide rays that add less than the threshold to their pixel’s colour, and the rays that branch off them.'),
          },
          rays.hideNegligible,
          (hideNegligible) => set({ hideNegligible }),
        ),
        this.slider(
          {
            name: 'negligibleThreshold',
            label: msg('Negligible below'),
            tooltip: msg('A ray that adds less than this share of its pixel’s colour counts as negligible. Type up to 100 %.'),
            ...NEGLIGIBLE_THRESHOLD,
            unit: '%',
            disabled: !rays.hideNegligible,
          },
          rays.negligibleThreshold,
          (negligibleThreshold) => set({ negligibleThreshold }),
        ),
        this.slider(
          {
            name: 'transparency',
            label: msg('Transparency'),
            tooltip: msg('See through the rays: 0 % is solid, 100 % almost invisible.'),
            min: 0,
            max: 1,
            step: 0.01,
            unit: '%',
          },
          rays.transparency,
          (transparency) => set({ transparency }),
        ),
      ])}
      ${this.section(msg('Ray thickness'), 'rays-radius', [
        this.switch(
          {
            name: 'dynamicRadius',
            label: msg('Thickness from contribution'),
            tooltip: msg('Draw each ray between the minimum and maximum radius by how much it adds to its pixel.'),
          },
          rays.dynamicRadius,
          (dynamicRadius) => set({ dynamicRadius }),
        ),
        this.radiusSlider('radius', msg('Radius'), msg('How thick every ray is drawn.'), rays.radius, rays.dynamicRadius, (radius) => set({ radius })),
        this.radiusSlider(
          'minRadius',
          msg('Radius at 0 %'),
          msg('Radius of a ray that adds nothing to its pixel. It may be larger than the radius at 100 %, to make small contributions stand out.'),
          rays.minRadius,
          !rays.dynamicRadius,
          (minRadius) => set({ minRadius }),
        ),
        this.radiusSlider(
          'maxRadius',
          msg('Radius at 100 %'),
          msg('Radius of a ray that makes the whole pixel colour.'),
          rays.maxRadius,
          !rays.dynamicRadius,
          (maxRadius) => set({ maxRadius }),
        ),
      ])}
      ${this.section(msg('Ray colours'), 'rays-colour', [
        this.switch(
          {
            name: 'contributionColor',
            label: msg('Fade by contribution'),
            tooltip: msg('Darken each ray by how little it adds to its pixel: full colour at 100 %, faint at 0.1 % and below.'),
          },
          rays.contributionColor,
          (contributionColor) => set({ contributionColor }),
        ),
        this.switch(
          {
            name: 'colorBlindPalette',
            label: msg('Colour-blind-safe colours'),
            tooltip: msg('Use the Okabe–Ito colours, which people with every kind of colour vision can tell apart.'),
          },
          rays.colorBlindPalette,
          (colorBlindPalette) => set({ colorBlindPalette }),
        ),
        this.switch(
          {
            name: 'colorByTime',
            label: msg('Colour by time'),
            tooltip: msg(
              'Colour each ray by the moment in the open shutter it was sent: dark violet at the start, yellow at the end (needs more than 1 time sample).',
            ),
          },
          rays.colorByTime,
          (colorByTime) => set({ colorByTime }),
        ),
        this.shows('legend') ? html`<rt-ray-legend data-guide=${ifDefined(this.guideOf('legend'))}></rt-ray-legend>` : nothing,
      ])}
      ${this.section(msg('Animation'), 'rays-animation', [
        this.switch(
          { name: 'animate', label: msg('Animate rays'), tooltip: msg('Let the rays grow from the camera, each one starting when the ray before it arrives.') },
          rays.animate,
          (animate) => set({ animate }),
        ),
        this.slider(
          {
            name: 'animationSpeed',
            label: msg('Speed'),
            tooltip: msg('How fast the rays grow, in metres per second. Type up to 100 m/s.'),
            ...SPEED,
            unit: 'm/s',
            disabled: !rays.animate,
          },
          rays.animationSpeed,
          (animationSpeed) => set({ animationSpeed }),
        ),
        this.switch(
          {
            name: 'animatePixelByPixel',
            label: msg('Pixel by pixel'),
            tooltip: msg('Grow one pixel’s rays after another, row by row, instead of all at once.'),
          },
          rays.animatePixelByPixel,
          (animatePixelByPixel) => set({ animatePixelByPixel }),
        ),
        this.switch({ name: 'loop', label: msg('Loop'), tooltip: msg('Start the animation again after a short pause.') }, rays.loop, (loop) => set({ loop })),
      ])}
    `;
  }

  /** A radius slider in centimetres over a value in metres. */
  private radiusSlider(
    name: 'radius' | 'minRadius' | 'maxRadius',
    label: string,
    tooltip: string,
    metres: number,
    disabled: boolean,
    action: (metres: number) => LabAction,
  ) {
    return this.slider({ name, label, tooltip, ...RADIUS_CM, unit: 'cm', disabled }, metres * CM_PER_M, (cm) => action(cm / CM_PER_M));
  }
}

customElements.define('rt-ray-panel', RtRayPanel);

declare global {
  interface HTMLElementTagNameMap {
    'rt-ray-panel': RtRayPanel;
  }
}
