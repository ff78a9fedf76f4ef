import { msg, str } from '@lit/localize';
import { LIMITS } from '../../../scene/scene-limits.ts';
import type { SliderSpec, VectorSpec } from './store-panel.ts';

/**
 * The controls of distributed ray tracing (distribution-effects §4): the lens and the
 * shutter in the ray tracer panel, gloss and movement in the object panel. The sliders stop
 * where a lesson needs them; typing reaches the schema's limits.
 */

export function apertureSpec(): SliderSpec<'aperture'> {
  return {
    name: 'aperture',
    label: msg('Aperture (lens radius)'),
    tooltip: msg('The radius of the camera’s lens in metres. 0 is a pinhole: everything is sharp. A wider lens blurs what is not on the plane in focus.'),
    min: LIMITS.aperture[0],
    max: 0.3,
    step: 0.005,
    inputMax: LIMITS.aperture[1],
    unit: 'm',
  };
}

export function focusDistanceSpec(): SliderSpec<'focusDistance'> {
  return {
    name: 'focusDistance',
    label: msg('Focus distance'),
    tooltip: msg('How far ahead of the camera the plane in focus is, in metres. Points on that plane stay sharp at any aperture.'),
    min: 0.5,
    max: 15,
    step: 0.05,
    inputMin: LIMITS.focusDistance[0],
    inputMax: LIMITS.focusDistance[1],
    unit: 'm',
  };
}

export function lensSamplesSpec(disabled: boolean): SliderSpec<'lensSamples'> {
  return {
    name: 'lensSamples',
    label: msg('Lens samples (n)'),
    tooltip: disabled
      ? msg('n × n rays from points on the lens per pixel sample. Open the aperture to use it.')
      : msg('n × n rays from points on the lens per pixel sample: less noise in the blur, n² times the work.'),
    min: LIMITS.lensSamples[0],
    max: LIMITS.lensSamples[1],
    step: 1,
    whole: true,
    disabled,
  };
}

/**
 * What the lens-samples setting sends per pixel sample, as the tracer does it
 * (render-pixel.ts): a pinhole sends one ray whatever n is, and n = 1 with an open lens one
 * ray from a random point of the lens (docs/tracer.md), not "1 × 1 = 1 lens rays".
 */
export function lensSamplesHint(n: number, aperture: number): string {
  if (aperture === 0) return msg('A pinhole: one ray per sample');
  if (n === 1) return msg('One lens ray per sample, from a random point of the lens');
  return msg(str`${n} × ${n} = ${n * n} lens rays per sample`);
}

export function timeSamplesSpec(): SliderSpec<'timeSamples'> {
  return {
    name: 'timeSamples',
    label: msg('Time samples (k)'),
    tooltip: msg('k moments while the shutter is open, per pixel sample: moving objects blur along their path. k times the work.'),
    min: LIMITS.timeSamples[0],
    max: LIMITS.timeSamples[1],
    step: 1,
    whole: true,
  };
}

export function roughnessSpec(): SliderSpec<'roughness'> {
  return {
    name: 'roughness',
    label: msg('Roughness (ρ)'),
    tooltip: msg('How far reflected (and, for glass, refracted) rays spread: 0 is a perfect mirror or clear glass, higher blurs the reflection.'),
    min: LIMITS.roughness[0],
    max: LIMITS.roughness[1],
    step: 0.01,
  };
}

export function glossySamplesSpec(disabled: boolean): SliderSpec<'glossySamples'> {
  return {
    name: 'glossySamples',
    label: msg('Glossy samples (m)'),
    tooltip: disabled
      ? msg('m × m spread rays per hit on a rough surface. Raise the roughness to use it.')
      : msg('m × m spread rays per hit on a rough surface: a smoother blur, m² times the rays at every bounce.'),
    min: LIMITS.glossySamples[0],
    max: LIMITS.glossySamples[1],
    step: 1,
    whole: true,
    disabled,
  };
}

export function velocitySpec(): VectorSpec<'velocity'> {
  const [min, max] = LIMITS.velocity;
  return {
    name: 'velocity',
    label: msg('Movement while the shutter is open'),
    tooltip: msg('How far the object moves, in metres, while the shutter is open (x right, y up, z toward you). Needs more than 1 time sample to show a blur.'),
    min,
    max,
    step: 0.05,
    unit: 'm',
  };
}
