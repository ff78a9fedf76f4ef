import { msg, str } from '@lit/localize';
import type { RayNode } from '../../tracer/ray-tree.ts';
import type { RayColorKey } from '../../view/ray-palette.ts';
import { rayColorKeyName } from './ray-names.ts';

// The words for one traced ray, in the legend's terms (ray-names.ts): only the tooltip of a
// ray pointed at and the ray debugger say them, and both load after the first screen, so
// these are not in its load.

/** The name of a traced ray (tooltip, debugger): its legend name, or its cone's. */
export function rayName(ray: Pick<RayNode, 'type' | 'hit' | 'untested'>): string {
  switch (ray.type) {
    case 'area-light':
      return ray.untested ? msg('Directions to an area light — not tested, Shadows is off (cone)') : msg('Shadow rays to an area light — all reach it (cone)');
    case 'area-shadow':
      return msg('Shadow rays to an area light — all blocked (cone)');
    case 'light':
      return rayColorKeyName(ray.untested ? 'untested' : 'light');
    default:
      return rayColorKeyName(ray.type);
  }
}

/**
 * What a hovered line ran into or stands for, in one sentence, or null when there is nothing
 * to say; `name` gives an object's or light's name as the scene list shows it.
 */
export function rayTargetText(node: RayNode, drawnAs: RayColorKey, name: (id: string | null) => string): string | null {
  if (drawnAs === 'normal') return msg(str`The normal at the hit on ${name(node.objectId)}: straight out of the surface, on the side the ray came from.`);
  if (!node.hit) return msg('Hit nothing: brings back the background colour');
  const light = name(node.lightId);
  if (node.type === 'shadow' || node.type === 'area-shadow') {
    return node.objectId ? msg(str`Blocked by ${name(node.objectId)} on its way to ${light}`) : msg(str`Blocked on its way to ${light}`);
  }
  if (node.untested) return msg(str`Not tested: Shadows is off, so no shadow ray was cast and ${light} counts as reaching this point, even through an object.`);
  if (node.type === 'light' || node.type === 'area-light') return msg(str`Reaches ${light}: nothing is in the way`);
  return node.objectId ? msg(str`Hits ${name(node.objectId)}`) : null;
}
