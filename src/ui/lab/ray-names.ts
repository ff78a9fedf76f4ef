import { msg } from '@lit/localize';
import type { RayColorKey } from '../../view/ray-palette.ts';

/**
 * The words the ray legend, tooltip, panel and debugger use for ray kinds (translated). One
 * meaning of "shadow ray" everywhere, the textbooks' (Shirley and Marschner, "Fundamentals of
 * Computer Graphics", §4.7 "Shadows"; pbrt's shadow rays): a ray from a hit point toward a light that tests whether
 * anything is in the way. It reaches the light (yellow) or is blocked (grey); with Shadows off
 * none is cast, and the lab draws only the direction to the light, "not tested".
 */

/** The legend's name for what a line is drawn as. */
export function rayColorKeyName(key: RayColorKey): string {
  switch (key) {
    case 'primary':
      return msg('Primary ray');
    case 'light':
      return msg('Shadow ray — reaches the light');
    case 'shadow':
      return msg('Shadow ray — blocked');
    case 'untested':
      return msg('Direction to the light — not tested, Shadows is off');
    case 'reflect':
      return msg('Reflected ray');
    case 'refract':
      return msg('Refracted ray');
    case 'no-hit':
      return msg('Hit nothing');
    case 'normal':
      return msg('Normal');
  }
}

/** One sentence a student can read next to the legend entry. */
export function rayColorKeyHint(key: RayColorKey): string {
  switch (key) {
    case 'primary':
      return msg('From the camera through a pixel.');
    case 'light':
      return msg(
        'A shadow ray tests whether anything is between the point and a light. This one reaches the light, so the light adds to the point’s colour. A cone: many shadow rays to an area light, all reaching it.',
      );
    case 'shadow':
      return msg(
        'A shadow ray tests whether anything is between the point and a light. This one is blocked, so that light adds nothing: the point is in its shadow. A cone: many shadow rays to an area light, all blocked.',
      );
    case 'untested':
      return msg(
        'With Shadows off the tracer casts no shadow rays: every light reaches every point, even through an object. The dotted line only shows the direction to the light.',
      );
    case 'reflect':
      return msg('Bounces off a shiny surface.');
    case 'refract':
      return msg('Bends into or out of a transparent object.');
    case 'no-hit':
      return msg('Meets no object and brings back the background colour (drawn 10 m long).');
    case 'normal':
      return msg(
        'The surface normal N at a hit point: straight out of the surface, on the side the ray came from. Drawn at the hits of the selected pixel’s rays.',
      );
  }
}
