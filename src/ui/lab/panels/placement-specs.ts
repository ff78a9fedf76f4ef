import { msg } from '@lit/localize';
import { LIMITS } from '../../../scene/scene-limits.ts';
import type { VectorSpec } from './store-panel.ts';

/** The position, rotation and scale fields of the object and light panels (typed ranges from LIMITS). */

export function positionSpec(): VectorSpec<'position'> {
  const [min, max] = LIMITS.coordinate;
  return { name: 'position', label: msg('Position'), tooltip: msg('Where it is, in metres (x right, y up, z toward you).'), min, max, step: 0.01, unit: 'm' };
}

export function rotationSpec(): VectorSpec<'rotation'> {
  const [min, max] = LIMITS.coordinate;
  return {
    name: 'rotation',
    label: msg('Rotation'),
    tooltip: msg('Turns about the x, y and z axes, in degrees (applied in that order).'),
    min,
    max,
    step: 0.1,
    unit: '°',
  };
}

export function scaleSpec(): VectorSpec<'scale'> {
  const [min, max] = LIMITS.scale;
  return { name: 'scale', label: msg('Scale'), tooltip: msg('Size along each axis: 1 is the unit shape, 2 twice as big.'), min, max, step: 0.01 };
}
