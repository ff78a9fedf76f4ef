import { z } from 'zod';
import type { DeclaredView } from '../lab-state/lab-action.ts';
import { DEFAULT_RAY_VIEW } from '../lab-state/lab-state.ts';
import { reasonIssue, withReason } from '../scene/scene-issues.ts';
import { optionChanges } from './option-changes.ts';

/**
 * A level's or task's `view` (docs/levels.md, "Views"): what the 3D view frames and from
 * which side, the chosen pixel, the ray filters. Whether the names in `frame` and the pixel
 * exist in the level's scene is a level rule (level-rules.ts), checked once the whole file
 * is valid.
 */

/** The names `frame` takes besides the ids of the scene's objects and lights and a pixel's rays ("rays:3,1": lab-state/framed-rays.ts). */
export const FRAMED_PARTS = ['camera', 'pixel-rays'] as const;

const direction = z
  .tuple([z.number(), z.number(), z.number()])
  .refine(([x, y, z]) => Math.hypot(x, y, z) > 1e-6, { error: (issue) => withReason(issue, { code: 'zeroDirection' }) });

export const declaredViewSchema = z
  .strictObject({
    frame: z
      .array(z.string().min(1))
      .min(1)
      .max(12)
      .optional()
      .describe('What the 3D view fits: object or light ids, "camera", "pixel-rays", "rays:<column>,<row>".'),
    from: direction.optional().describe('The side the 3D view looks from, as a world direction towards what it frames.'),
    throughCamera: z.boolean().optional().describe('Look through the ray tracer\'s camera, as "Camera view" does.'),
    pixel: z
      .tuple([z.int().min(0), z.int().min(0)])
      .nullable()
      .optional()
      .describe('The pixel to choose [column, row], or null for none.'),
    rays: optionChanges(DEFAULT_RAY_VIEW).optional().describe("Ray options to set (the ray panel's), the rest unchanged."),
  })
  .superRefine((view, context) => {
    if (view.throughCamera && view.frame) {
      context.addIssue(reasonIssue(['throughCamera'], view.throughCamera, { code: 'frameAndCamera' }));
    }
    if (view.from && !view.frame) context.addIssue(reasonIssue(['from'], view.from, { code: 'fromWithoutFrame' }));
  });

type SameType<A, B> = [A] extends [B] ? ([B] extends [A] ? true : false) : false;
type Assert<T extends true> = T;

/** Compile-time guard that the schema produces the lab's DeclaredView. */
export type SchemaMatchesDeclaredView = Assert<SameType<z.output<typeof declaredViewSchema>, DeclaredView>>;
