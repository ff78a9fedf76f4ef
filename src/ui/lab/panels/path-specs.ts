import { msg, str } from '@lit/localize';
import { LIMITS } from '../../../scene/scene-limits.ts';
import type { ChoiceOption } from '../../controls/rt-choice.ts';
import type { ControlText, SliderSpec } from './store-panel.ts';

/**
 * The controls of path mode (spec path-tracing §1, docs/path-tracing.md) in the ray tracer
 * panel's "Path tracing" section: which estimator renders, N paths per pixel, how a diffuse
 * bounce picks its direction, light sampling, Russian roulette and the exposure. The texts
 * say what this tracer does (path-integrator.ts), in the words the chapter's levels use.
 */

export function integratorText(): ControlText<'integrator'> {
  return { name: 'integrator', label: msg('Tracer'), tooltip: msg('Which method computes the light of each pixel.') };
}

export function integratorOptions(): ChoiceOption[] {
  return [
    {
      value: 'whitted',
      label: msg('Whitted'),
      tooltip: msg('Only mirror and glass rays are followed; the light that bounces off walls is faked by the ambient term.'),
    },
    {
      value: 'path',
      label: msg('Path tracing'),
      tooltip: msg('Random paths that bounce off every surface (Kajiya 1986): light from walls is computed, not faked. Noisy with few paths.'),
    },
  ];
}

/** The slider stops at 256, where the chapter's noise lesson ends; typing reaches the schema's limit. */
export function pathSamplesSpec(): SliderSpec<'pathSamples'> {
  return {
    name: 'pathSamples',
    label: msg('Paths per pixel (N)'),
    tooltip: msg('N random paths per pixel, averaged (path tracing): more paths, less noise, more time. Type up to 65536.'),
    min: LIMITS.pathSamples[0],
    max: 256,
    step: 1,
    inputMax: LIMITS.pathSamples[1],
    whole: true,
  };
}

export function pathSamplesHint(n: number): string {
  return n === 1 ? msg('1 path per pixel') : msg(str`${n} paths per pixel`);
}

export function bounceSamplingText(): ControlText<'bounceSampling'> {
  return {
    name: 'bounceSampling',
    label: msg('Bounce direction'),
    tooltip: msg('How a path picks its new direction when it bounces off a matt surface (path tracing).'),
  };
}

export function bounceSamplingOptions(): ChoiceOption[] {
  return [
    {
      value: 'cosine',
      label: msg('Cosine'),
      tooltip: msg('More often close to the normal, where cos θ is large.'),
    },
    {
      value: 'uniform',
      label: msg('Uniform'),
      tooltip: msg('Every direction of the half sphere above the surface equally often.'),
    },
  ];
}

export function lightSamplingText(): ControlText<'lightSampling'> {
  return {
    name: 'lightSampling',
    label: msg('Light sampling'),
    tooltip: msg(
      'At every matt point of a path, also send a shadow ray to a random point on each area light. Without it, only paths that happen to hit the lamp see it. Point and spot lights are always sampled: no path can hit them.',
    ),
  };
}

export function russianRouletteText(): ControlText<'russianRoulette'> {
  return {
    name: 'russianRoulette',
    label: msg('Russian roulette'),
    tooltip: msg('From the second bounce on, end dim paths at random; the paths that go on count for more.'),
  };
}

export function exposureSpec(): SliderSpec<'exposure'> {
  return {
    name: 'exposure',
    label: msg('Exposure'),
    tooltip: msg('Stops: the path-traced picture is multiplied by 2 to this power before it is shown. +1 is twice as bright.'),
    min: -5,
    max: 5,
    step: 0.5,
    inputMin: LIMITS.exposure[0],
    inputMax: LIMITS.exposure[1],
  };
}

/** Path mode's maxDepth counts bounces after the first hit, as Cycles' "Max Bounces" (docs/path-tracing.md). */
export function maxBouncesText(): ControlText<'maxDepth'> {
  return {
    name: 'maxDepth',
    label: msg('Max bounces'),
    tooltip: msg(
      'How many times a path may bounce after the point the camera sees: 0 shows only direct light, each extra bounce adds light that bounced once more.',
    ),
  };
}
