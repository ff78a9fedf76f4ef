import { z } from 'zod';
import { wholeNumberIn } from '../../scene/scene-schema-parts.ts';
import { localizedTextSchema } from '../localized-text.ts';
import { COSINE_NORMALS } from './cosine-bounce-normals.ts';
import { MIRROR_EDGES } from './mirror-edges.ts';
import { PHONG_EDGES } from './phong-edges.ts';
import { RAY_BOX_EDGES } from './ray-box-edges.ts';
import { RAY_SPHERE_EDGES } from './ray-sphere-edges.ts';
import { REFRACTION_EDGES } from './refraction-edges.ts';
import { SHADOW_EDGES } from './shadow-edges.ts';

/** What every lab's goal holds besides its `lab` and its cases. */
const labFields = {
  function: z
    .string()
    .regex(/^[A-Za-z_$][\w$]*$/)
    .describe('The name the learner’s function must have.'),
  signature: z.string().min(1).max(200).describe('The call as the contract shows it, e.g. "hitSphere(origin, direction, center, radius)".'),
  contract: localizedTextSchema.describe('What comes in, what must come out, the units.'),
  skeleton: localizedTextSchema.describe('The starting code: the function with its steps as comments, per language (`{ "en": …, "nl": … }`) or one string.'),
};

/** The cases of a lab whose named edge cases are `edges`. */
const casesOf = <const Edges extends readonly [string, ...string[]]>(edges: Edges) =>
  z.strictObject({
    edges: z.array(z.enum(edges)).min(1).describe('The named edge cases, graded first and named in the result.'),
    random: wholeNumberIn([0, 1000]).describe('How many seeded random cases follow them.'),
    seed: wholeNumberIn([0, 2 ** 31 - 1]),
  });

/** One lab: its name, which is the grader (it knows the tracer's own function), and the edge cases it knows. */
const labGoal = <const Lab extends string, const Edges extends readonly [string, ...string[]]>(lab: Lab, edges: Edges) =>
  z.strictObject({
    lab: z.literal(lab).describe('Which of the tracer’s functions the learner writes; it is the reference and knows the cases.'),
    ...labFields,
    cases: casesOf(edges),
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
      labGoal('ray-sphere', RAY_SPHERE_EDGES),
      labGoal('mirror', MIRROR_EDGES),
      labGoal('refraction', REFRACTION_EDGES),
      labGoal('ray-box', RAY_BOX_EDGES),
      labGoal('shadow', SHADOW_EDGES),
      labGoal('phong', PHONG_EDGES),
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
      z.strictObject({
        lab: z.literal('cosine-bounce').describe('Cosine-weighted bounce directions, graded statistically (cosine-bounce-lab.ts).'),
        ...labFields,
        cases: z.strictObject({
          normals: z.array(z.enum(COSINE_NORMALS)).min(1).describe('The normals the function is run with, by name; each a kind of case.'),
          samples: wholeNumberIn([200, 2000]).describe('How many seeded runs per normal; enough directions for the χ² tests.'),
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
