import { z } from 'zod';
import type { LabActionType } from '../lab-state/lab-action.ts';
import { reasonIssue } from '../scene/scene-issues.ts';
import { wholeNumberIn } from '../scene/scene-schema-parts.ts';
import { challengeParSchema } from './challenge-par.ts';
import { actionFields, APP_ONLY_ACTION, LAB_ACTION_TYPES, labActionSchema } from './lab-action-schema.ts';
import { chosenBy } from './chosen-schema.ts';
import { COMPARISONS, conditionSchema, problemWithComparison, type Comparison, type JsonValue } from './condition.ts';
import { isRecord } from '../util/is-record.ts';
import { gotOf, type Reason } from '../util/issue.ts';
import { localizedTextSchema, type LocalizedText } from './localized-text.ts';
import { parsePath } from './state-path.ts';
import { CONTROL_TARGETS } from './lab-controls.ts';
import { codeGoalSchema, type CodeGoal } from './code-labs/code-goal.ts';

/**
 * What a task asks of the learner, as data (DESIGN.md: a discriminated union, not a pile of
 * booleans). A level file marks a goal's kind by the one field it has (`{ "event": … }`,
 * `{ "all": [ … ] }`; docs/levels.md has an example of each); the schema below parses it into
 * the tagged form the code uses, `{ kind: 'event', event: … }`, so that every place that
 * tells kinds apart is one `switch (goal.kind)` whose default the compiler checks is
 * unreachable (`const never: never = goal`), and every walk through nested goals goes
 * through `children`.
 */

/** Conditions per path, on the state (`where`) or on the action (`with`). */
export type Conditions = Record<string, JsonValue>;

/** Done when this action happens (`times` times since the task was shown, default once),
 * with these fields, leaving the state like this. */
export interface EventGoal {
  kind: 'event';
  event: LabActionType;
  with?: Conditions;
  where?: Conditions;
  times?: number;
}

/** Done while the state holds this value. */
export interface StateGoal {
  kind: 'state';
  state: string;
  op: Comparison;
  value: JsonValue;
}

/** Predict, then check: done when answered, right or wrong (the answer is recorded). */
export interface QuizGoal {
  kind: 'quiz';
  quiz: { question: LocalizedText; choices: LocalizedText[]; answer: number; explanation?: LocalizedText };
}

/**
 * Predict a number: done when answered; right when within `tolerance` of `answer` (a number
 * prediction of spec/challenges.md §1: a pixel's mix, a visible fraction, an attenuation).
 */
export interface EstimateGoal {
  kind: 'estimate';
  estimate: { question: LocalizedText; answer: number; tolerance: number; unit?: LocalizedText; explanation?: LocalizedText };
}

/**
 * Predict the picture: pick which of 2–4 small renders the tracer will make
 * (spec/challenges.md §1). Each choice is the level's starting scene changed by its actions
 * (the vocabulary of solutions), rendered by the tracer at thumbnail size.
 */
export type PictureGoal = z.output<typeof pictureGoalSchema>;

/**
 * Match the target picture (spec/challenges.md §2): done when a render of the learner's scene
 * comes within `measure.threshold` of the target's, both rendered by the tracer at
 * `measure.size` (challenge-closeness.ts says how they are compared). The app reports each
 * comparison as a `challenge.compared` action; the goal counts the close ones, as an event
 * goal counts its events.
 */
export type ChallengeGoal = z.output<typeof challengeGoalSchema>;

/** Read, then press Next (`{ "info": true }` in a level file). */
export interface InfoGoal {
  kind: 'info';
}

/** Done while every goal inside is. */
export interface AllGoal {
  kind: 'all';
  all: SceneGoal[];
}

/** Done while at least one goal inside is. */
export interface AnyGoal {
  kind: 'any';
  any: SceneGoal[];
}

/** The goals checked against the app's state and actions, which `all` and `any` combine. */
export type SceneGoal = EventGoal | StateGoal | AllGoal | AnyGoal;

/** Quiz, estimate and info goals are answered through the task panel, so they stand alone. */
export type Goal = SceneGoal | QuizGoal | EstimateGoal | PictureGoal | ChallengeGoal | CodeGoal | InfoGoal;

export type { CodeGoal };

/** Every kind of goal; a level file names it by the field that holds the goal's content. */
export type GoalKind = Goal['kind'];

/** A prediction the learner makes in the task panel: a choice (of words or pictures) or a number. */
export type PredictionGoal = QuizGoal | EstimateGoal | PictureGoal;

/** How the learner completes a task: read it, answer it, or do something in the lab. */
export const TASK_KINDS = ['info', 'quiz', 'do'] as const;
export type TaskKind = (typeof TASK_KINDS)[number];

export function kindOfGoal(goal: Goal): TaskKind {
  switch (goal.kind) {
    case 'info':
      return 'info';
    case 'quiz':
    case 'estimate':
    case 'picture':
      return 'quiz';
    case 'event':
    case 'state':
    case 'all':
    case 'any':
    case 'challenge':
    case 'code':
      return 'do';
    default: {
      const never: never = goal;
      return never;
    }
  }
}

/** The goal as a prediction (a choice or a number), or undefined for a goal done otherwise. */
export function predictionOf(goal: Goal): PredictionGoal | undefined {
  switch (goal.kind) {
    case 'quiz':
    case 'estimate':
    case 'picture':
      return goal;
    case 'info':
    case 'event':
    case 'state':
    case 'all':
    case 'any':
    case 'challenge':
    case 'code':
      return undefined;
    default: {
      const never: never = goal;
      return never;
    }
  }
}

/**
 * The question, explanation, key and form of a prediction, whichever kind it is: a choice
 * among `choices` (words or pictures) or, with `choices` 0, a number.
 */
export function predictionParts(goal: PredictionGoal): { question: LocalizedText; explanation?: LocalizedText; choices: number; answer: number } {
  switch (goal.kind) {
    case 'quiz':
      return { ...goal.quiz, choices: goal.quiz.choices.length };
    case 'picture':
      return { ...goal.picture, choices: goal.picture.choices.length };
    case 'estimate':
      return { ...goal.estimate, choices: 0 };
    default: {
      const never: never = goal;
      return never;
    }
  }
}

/** What a prediction's explanation is, whichever form it has. */
export function explanationOf(goal: PredictionGoal): LocalizedText | undefined {
  return predictionParts(goal).explanation;
}

const pathSyntax = z.string().superRefine((path, context) => {
  const parsed = parsePath(path);
  if (!parsed.ok) context.addIssue(reasonIssue([], path, parsed.reason));
});

const eventGoalSchema = z
  .strictObject({
    event: z.enum(LAB_ACTION_TYPES),
    with: z.record(pathSyntax, conditionSchema).optional(),
    where: z.record(pathSyntax, conditionSchema).optional(),
    times: wholeNumberIn([1, 100]).optional(),
  })
  .superRefine((goal, context) => {
    if (goal.event === APP_ONLY_ACTION) {
      context.addIssue(reasonIssue(['event'], goal.event, { code: 'appOnlyAction' }));
    }
    // `with` looks into the action, so its paths must start at one of that action's fields.
    const fields = actionFields(goal.event);
    for (const path of Object.keys(goal.with ?? {})) {
      const parsed = parsePath(path);
      const first = parsed.ok ? parsed.steps[0] : undefined;
      if (first?.kind === 'field' && !fields.includes(first.name)) {
        context.addIssue(reasonIssue(['with', path], path, { code: 'actionFields', event: goal.event, fields }));
      }
    }
  })
  .transform((goal) => ({ kind: 'event' as const, ...goal }));

const stateGoalSchema = z
  .strictObject({ state: pathSyntax, op: z.enum(COMPARISONS), value: z.json() })
  .superRefine((goal, context) => {
    const problem = problemWithComparison(goal.op, goal.value);
    if (problem) context.addIssue(reasonIssue(['value'], goal.value, problem));
  })
  .transform((goal) => ({ kind: 'state' as const, ...goal }));

const quizGoalSchema = z
  .strictObject({
    quiz: z
      .strictObject({
        question: localizedTextSchema,
        choices: z.array(localizedTextSchema).min(2).max(6),
        answer: wholeNumberIn([0, 5]).describe('The position of the right choice, counting from 0.'),
        explanation: localizedTextSchema.optional().describe('Shown once the learner has observed the result: why the answer is what it is.'),
      })
      .superRefine((quiz, context) => {
        if (quiz.answer >= quiz.choices.length) {
          context.addIssue(reasonIssue(['answer'], quiz.answer, { code: 'choiceOutOfRange', last: quiz.choices.length - 1 }));
        }
      }),
  })
  .transform((goal) => ({ kind: 'quiz' as const, ...goal }));

const estimateGoalSchema = z
  .strictObject({
    estimate: z.strictObject({
      question: localizedTextSchema,
      answer: z.number().describe('The right value.'),
      tolerance: z.number().min(0).describe('How far from the answer a prediction may be and still be right.'),
      unit: localizedTextSchema.optional().describe('Shown after the number box, e.g. "m" or "%".'),
      explanation: localizedTextSchema.optional().describe('Shown once the learner has observed the result: why the value is what it is.'),
    }),
  })
  .transform((goal) => ({ kind: 'estimate' as const, ...goal }));

const pictureGoalSchema = z
  .strictObject({
    picture: z
      .strictObject({
        question: localizedTextSchema,
        choices: z
          .array(
            z.strictObject({ actions: z.array(labActionSchema).min(1).max(10).describe("The changes to the level's starting scene that make this picture.") }),
          )
          .min(2)
          .max(4),
        answer: wholeNumberIn([0, 3]).describe('The position of the right picture, counting from 0.'),
        explanation: localizedTextSchema.optional().describe('Shown once the learner has observed the result: why the picture is what it is.'),
      })
      .superRefine((picture, context) => {
        if (picture.answer >= picture.choices.length) {
          context.addIssue(reasonIssue(['answer'], picture.answer, { code: 'choiceOutOfRange', last: picture.choices.length - 1 }));
        }
      }),
  })
  .transform((goal) => ({ kind: 'picture' as const, ...goal }));

/** The size of the pictures a challenge compares when the level does not say: small, so that both render well under a second. */
export const CHALLENGE_SIZE: readonly [number, number] = [64, 48];

const challengeGoalSchema = z
  .strictObject({
    challenge: z.strictObject({
      target: z
        .array(labActionSchema)
        .min(1)
        .max(10)
        .describe("The changes to the level's starting scene that make the target picture; the learner never sees them."),
      editable: z.array(z.enum(CONTROL_TARGETS)).min(1).max(6).describe('The controls the learner may use; the level shows only these (the rest is locked).'),
      measure: z.strictObject({
        size: z
          .tuple([wholeNumberIn([8, 160]), wholeNumberIn([8, 120])])
          .default([CHALLENGE_SIZE[0], CHALLENGE_SIZE[1]])
          .describe('Width and height of both pictures compared, in pixels.'),
        threshold: z.number().gt(0).max(1).describe('The largest mean difference per pixel and colour channel, in linear light (0–1), that counts as a match.'),
      }),
      par: challengeParSchema,
    }),
  })
  .transform((goal) => ({ kind: 'challenge' as const, ...goal }));

const infoGoalSchema = z.strictObject({ info: z.literal(true) }).transform((): InfoGoal => ({ kind: 'info' }));

const innerGoals = () => z.array(z.lazy(() => sceneGoalSchema)).min(1);

/**
 * Each kind's schema, under the name of the field that marks it in a level file (which is
 * also its `kind`). Keyed by the kinds themselves, so a new kind in the union above does
 * not compile until it has a schema here.
 */
const SCENE_GOAL_SCHEMAS: { [Kind in SceneGoal['kind']]: z.ZodType<Extract<SceneGoal, { kind: Kind }>> } = {
  event: eventGoalSchema,
  state: stateGoalSchema,
  all: z.strictObject({ all: innerGoals() }).transform((goal) => ({ kind: 'all' as const, ...goal })),
  any: z.strictObject({ any: innerGoals() }).transform((goal) => ({ kind: 'any' as const, ...goal })),
};
const GOAL_SCHEMAS: { [Kind in GoalKind]: z.ZodType<Extract<Goal, { kind: Kind }>> } = {
  ...SCENE_GOAL_SCHEMAS,
  quiz: quizGoalSchema,
  estimate: estimateGoalSchema,
  picture: pictureGoalSchema,
  challenge: challengeGoalSchema,
  code: codeGoalSchema,
  info: infoGoalSchema,
};

/** Every goal kind, in the order docs/levels.md lists them. */
export const GOAL_KINDS = Object.keys(GOAL_SCHEMAS) as GoalKind[];

/** The kinds that are a task's whole goal, never inside `all` or `any`. */
const STAND_ALONE_KINDS = GOAL_KINDS.filter((kind) => !(kind in SCENE_GOAL_SCHEMAS));

function chooseByField<Output>(kinds: Record<string, z.ZodType<Output>>, standAlone: readonly string[]) {
  const names = Object.keys(kinds);
  return (input: unknown): z.ZodType<Output> | Reason => {
    if (!isRecord(input)) return { code: 'notAGoal', fields: names, got: gotOf(input) };
    const alone = standAlone.find((name) => name in input);
    if (alone) return { code: 'goalStandsAlone', kind: alone };
    const present = names.filter((name) => name in input);
    if (present.length === 0) return { code: 'noGoalField', fields: names };
    if (present.length > 1) return { code: 'manyGoalFields', fields: names, present };
    return kinds[present[0]];
  };
}

const sceneGoalSchema: z.ZodType<SceneGoal> = chosenBy(chooseByField<SceneGoal>(SCENE_GOAL_SCHEMAS, STAND_ALONE_KINDS));
export const goalSchema: z.ZodType<Goal> = chosenBy(chooseByField<Goal>(GOAL_SCHEMAS, []));

/** A goal directly inside another, with the steps from that goal to it as a level file writes them (`["all", 0]`). */
export interface GoalChild {
  goal: SceneGoal;
  steps: [kind: 'all' | 'any', index: number];
}

/**
 * The goals directly inside `goal`, in file order: the one place that knows which kinds
 * hold other goals. Every walk through nested goals (`goalParts` and all its users) goes
 * through here, so a new kind that holds goals is entered everywhere once it is listed here.
 */
export function children(goal: Goal): GoalChild[] {
  switch (goal.kind) {
    case 'all':
      return goal.all.map((part, index) => ({ goal: part, steps: ['all', index] }));
    case 'any':
      return goal.any.map((part, index) => ({ goal: part, steps: ['any', index] }));
    case 'event':
    case 'state':
    case 'quiz':
    case 'estimate':
    case 'picture':
    case 'challenge':
    case 'code':
    case 'info':
      return [];
    default: {
      const never: never = goal;
      return never;
    }
  }
}

/** Every goal inside `goal` at any depth (itself first), each with its path from it, for checks that look at each. */
export function goalParts(goal: Goal, path: (string | number)[] = []): { goal: Goal; path: (string | number)[] }[] {
  return [{ goal, path }, ...children(goal).flatMap((child) => goalParts(child.goal, [...path, ...child.steps]))];
}

type Assert<T extends true> = T;
type SameType<A, B> = [A] extends [B] ? ([B] extends [A] ? true : false) : false;

/** Compile-time guard that the kinds' schemas produce the interfaces above. */
export type SchemaMatchesGoalTypes = [
  Assert<SameType<z.output<typeof eventGoalSchema>, EventGoal>>,
  Assert<SameType<z.output<typeof stateGoalSchema>, StateGoal>>,
  Assert<SameType<z.output<typeof quizGoalSchema>, QuizGoal>>,
  Assert<SameType<z.output<typeof estimateGoalSchema>, EstimateGoal>>,
  Assert<SameType<z.output<typeof infoGoalSchema>, InfoGoal>>,
  Assert<SameType<z.output<typeof pictureGoalSchema>, PictureGoal>>,
  Assert<SameType<z.output<typeof challengeGoalSchema>, ChallengeGoal>>,
];
