import { z } from 'zod';
import { wholeNumberIn } from '../../scene/scene-schema-parts.ts';
import { localizedTextSchema } from '../localized-text.ts';
import { RAY_BOX_EDGES } from './ray-box-edges.ts';
import { RAY_SPHERE_EDGES } from './ray-sphere-edges.ts';

/** What every lab's goal says besides its cases: the function, its contract and its skeleton. */
const labFields = {
  function: z
    .string()
    .regex(/^[A-Za-z_$][\w$]*$/)
    .describe('The name the learner’s function must have.'),
  signature: z.string().min(1).max(200).describe('The call as the contract shows it, e.g. "hitSphere(origin, direction, center, radius)".'),
  contract: localizedTextSchema.describe('What comes in, what must come out, the units.'),
  skeleton: localizedTextSchema.describe('The starting code: the function with its steps as comments, per language (`{ "en": …, "nl": … }`) or one string.'),
};

/** A lab graded on its named edge cases (each lab its own list) and seeded random cases. */
const casesOf = <const Edges extends readonly [string, ...string[]]>(edges: Edges) =>
  z.strictObject({
    edges: z.array(z.enum(edges)).min(1).describe('The named edge cases, graded first and named in the result.'),
    random: wholeNumberIn([0, 1000]).describe('How many seeded random cases follow them.'),
    seed: wholeNumberIn([0, 2 ** 31 - 1]),
  });

/**
 * A code lab's goal (spec/code-labs.md §1): write one function of the tracer, with its
 * signature and contract in the learner's language, starting from a skeleton; done when
 * every case passes (code-lab-grading.ts). `lab` names the grader, which knows the tracer's
 * own function and the named edge cases the level may list. In a level file:
 * `{ "code": { "lab": "ray-sphere", "function": "hitSphere", … } }`.
 */
export const codeGoalSchema = z
  .strictObject({
    code: z.discriminatedUnion('lab', [
      z.strictObject({ lab: z.literal('ray-sphere').describe('Ray–sphere intersection (ray-sphere-lab.ts).'), ...labFields, cases: casesOf(RAY_SPHERE_EDGES) }),
      z.strictObject({ lab: z.literal('ray-box').describe('The AABB slab test (ray-box-lab.ts).'), ...labFields, cases: casesOf(RAY_BOX_EDGES) }),
      z.strictObject({
        lab: z.literal('pixel-samples').describe('Jittered samples in a pixel, graded statistically (pixel-samples-lab.ts).'),
        ...labFields,
        cases: z.strictObject({
          sizes: z
            .array(wholeNumberIn([1, 256]).refine((n) => Number.isInteger(Math.sqrt(n)), 'a square: 1, 4, 9, 16…'))
            .min(1)
            .describe('The numbers of samples n the runs ask for, in turn; each a square.'),
          runs: wholeNumberIn([50, 1000]).describe('How many seeded runs; enough points for the χ² test.'),
          seed: wholeNumberIn([0, 2 ** 31 - 1]),
        }),
      }),
    ]),
  })
  .transform((goal) => ({ kind: 'code' as const, ...goal }));

/** Done once a run of the learner's function passes every case. */
export type CodeGoal = z.output<typeof codeGoalSchema>;

/** The labs there are: which of the tracer's functions the learner writes. */
export type CodeLab = CodeGoal['code']['lab'];
