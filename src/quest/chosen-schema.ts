import { z } from 'zod';
import { describeIssue, reasonIssue } from '../scene/scene-issues.ts';
import type { Reason } from '../util/issue.ts';

/**
 * A schema that looks at its input to choose which schema checks it: the goal kind by the
 * field it has (`event`, `state`, `quiz`…), a text by being a string or an object.
 *
 * zod's own unions report a failed input with one line per option (or just "Invalid
 * input"), which tells an author little; after choosing, every problem is reported where it
 * stands, e.g. `tasks[2].goal.op: must be one of ==, !=, …`. `choose` returns a reason
 * (src/util/issue.ts) instead of a schema when it cannot choose.
 */
export function chosenBy<Output>(choose: (input: unknown) => z.ZodType<Output> | Reason) {
  return z.unknown().transform((input, context): Output => {
    const chosen = choose(input);
    if (!(chosen instanceof z.ZodType)) {
      context.addIssue(reasonIssue([], input, chosen));
      return z.NEVER;
    }
    const result = chosen.safeParse(input, { error: describeIssue });
    if (result.success) return result.data;
    // Issues keep their paths (relative to this input): zod prefixes them with ours.
    for (const issue of result.error.issues) context.addIssue({ ...issue });
    return z.NEVER;
  });
}
