import { msg } from '@lit/localize';
import type { RenderLab } from '../../../quest/code-labs/lab-render/lab-functions.ts';

/** What the three pictures of one view of a lab render are, for their captions' text alternatives. */
export interface ViewLabels {
  mine: string;
  reference: string;
  difference: string;
}

/**
 * The labs whose render adds the view from straight above (axis-view.ts): the box lab, whose
 * slab test has a case of its own for a ray parallel to a slab, and none of the level camera's
 * rays is.
 */
export const viewsAlongAxis = (lab: RenderLab): boolean => lab === 'ray-box';

/** The pictures of the level's own view. */
export const levelViewLabels = (): ViewLabels => ({
  mine: msg('The level’s scene rendered with your function.'),
  reference: msg('The level’s scene rendered with the tracer’s own function, the reference.'),
  difference: msg('The difference between the two pictures'),
});

/** The pictures of the view from straight above. */
export const axisViewLabels = (): ViewLabels => ({
  mine: msg('The scene seen from straight above, rendered with your function.'),
  reference: msg('The scene seen from straight above, rendered with the tracer’s own function, the reference.'),
  difference: msg('The difference between the two pictures from above'),
});

export const axisViewTitle = () => msg('Rays straight along an axis');

/** Why the second view is there: the level's camera has no ray with a zero component. */
export const axisViewWhy = () =>
  msg(
    'The same scene from straight above. Every ray goes straight down, along −y: direction.x and direction.z are exactly 0, so each ray is parallel to the x slab and to the z slab. None of the level camera’s rays has a component of exactly 0, so only this view shows how your function treats a ray parallel to a slab (not one exactly in a face’s plane: only Run tests checks that).',
  );
