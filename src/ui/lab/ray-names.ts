import { msg } from '@lit/localize';
import type { RayType } from '../../tracer/ray-tree.ts';
import type { RayColorKey } from '../../view/ray-palette.ts';

/** The words the ray legend, tooltip and panel use for ray kinds (translated). */

/** The legend's name for what a ray is drawn as. */
export function rayColorKeyName(key: RayColorKey): string {
  switch (key) {
    case 'primary':
      return msg('Primary ray');
    case 'light':
      return msg('Light ray');
    case 'shadow':
      return msg('Shadow ray');
    case 'reflect':
      return msg('Reflected ray');
    case 'refract':
      return msg('Refracted ray');
    case 'no-hit':
      return msg('Hit nothing');
  }
}

/** One sentence a student can read next to the legend entry. */
export function rayColorKeyHint(key: RayColorKey): string {
  switch (key) {
    case 'primary':
      return msg('From the camera through a pixel.');
    case 'light':
      return msg('Reaches a light and lights the point. A cone: many rays to an area light.');
    case 'shadow':
      return msg('Blocked on its way to a light: the point is in shadow. A cone: many blocked rays to an area light.');
    case 'reflect':
      return msg('Bounces off a shiny surface.');
    case 'refract':
      return msg('Bends into or out of a transparent object.');
    case 'no-hit':
      return msg('Meets no object and brings back the background colour (drawn 10 m long).');
  }
}

/** The tooltip's name for a traced ray's type. */
export function rayTypeName(type: RayType): string {
  switch (type) {
    case 'area-light':
      return msg('Light rays to an area light (cone)');
    case 'area-shadow':
      return msg('Shadow rays to an area light (cone)');
    default:
      return rayColorKeyName(type);
  }
}
