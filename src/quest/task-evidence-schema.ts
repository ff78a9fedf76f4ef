import { z } from 'zod';
import { withReason } from '../scene/scene-issues.ts';
import { RAY_PATH_KINDS, RAY_PATH_PATTERN } from '../tracer/ray-path.ts';

/**
 * A task's `evidence` (docs/levels.md, "Evidence"): the things its text tells the learner to
 * look at in the 3D view, so that a browser test can check that its start view shows them,
 * large enough and under no panel (e2e/guide-targets.spec.ts). The game itself does nothing
 * with it. Whether the ids and the pixel exist in the scene is a level rule (level-rules.ts).
 */
export const taskEvidenceSchema = z.strictObject({
  objects: z.array(z.string().min(1)).min(1).max(12).optional().describe('Ids of the objects and lights the text names.'),
  rays: z
    .strictObject({
      pixel: z.tuple([z.int().min(0), z.int().min(0)]).describe('The pixel whose rays the text names, [column, row].'),
      paths: z
        .array(
          z.string().regex(RAY_PATH_PATTERN, {
            error: (issue) => withReason(issue, { code: 'rayPathKinds', kinds: RAY_PATH_KINDS.slice(1) }),
          }),
        )
        .min(1)
        .max(12)
        .describe('Each ray the text names, by the kinds on the way to it: "primary/shadow".'),
    })
    .optional(),
});

export type TaskEvidence = z.output<typeof taskEvidenceSchema>;
