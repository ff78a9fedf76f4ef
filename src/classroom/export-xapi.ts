import type { LoggedEvent } from '../quest/event-log.ts';
import { fnv1a } from './assignment-id.ts';
import { hintsOpened, readLog } from './task-attempts.ts';
import type { ChallengeTries } from './challenge-attempt.ts';
import type { CodeRuns } from './code-lab-attempt.ts';
import { assignmentLabel, exportOwner, type ExportInput } from './export-context.ts';
import { isoAt, isoDuration } from './iso-duration.ts';
import { NO_OPTION_TEXTS, optionId, type OptionText } from './quiz-options.ts';
import { activities, EXTENSIONS, VERBS, XAPI_BASE, type XapiActivity, type XapiVerb } from './xapi-vocabulary.ts';

/**
 * The xAPI export (https://github.com/adlnet/xAPI-Spec, version 1.0.3): a list of statements
 * that a teacher can send to their school's learning record store. Each has an id, an actor,
 * a verb, an activity, a timestamp and where it fits a result; durations are ISO 8601.
 *
 * Statement ids are derived from their content, so sending the same file twice does not
 * record anything twice (the store refuses a known id). Render and tab events and hint
 * offers are left out: they are the app's, not learning; the JSON export has them. A quiz
 * answer's response is the chosen option's id (a, b, … by its place in the level file,
 * quiz-options.ts), with its text in an extension. A task's
 * completion says how many hints were offered and how many the learner opened; each rung
 * shown is an "experienced" statement of its own, with its trigger (event-log.ts).
 *
 * The actor is an account on the school's home page (the assignment's `xapiHomePage`, else
 * the app's own address), named by the participant code or, without one, by the browser's
 * install id. `context.registration` is the attempt id, so that two playthroughs by one
 * code stay apart (xAPI 1.0.3 §4.1.6).
 */

export interface XapiAgent {
  objectType: 'Agent';
  account: { homePage: string; name: string };
}

export interface XapiResult {
  success?: boolean;
  completion?: boolean;
  score?: { raw: number; min: number };
  duration?: string;
  response?: string;
  extensions?: Record<string, string | number>;
}

export interface XapiStatement {
  id: string;
  actor: XapiAgent;
  verb: XapiVerb;
  object: XapiActivity;
  result?: XapiResult;
  context: {
    registration: string;
    platform: string;
    language: string;
    contextActivities: { parent?: XapiActivity[]; grouping: XapiActivity[] };
    extensions: Record<string, string>;
  };
  timestamp: string;
}

export function exportXapi(input: ExportInput): XapiStatement[] {
  const { progress, assignment } = input;
  const { startedAt, events } = progress.log;
  const owner = exportOwner(input);
  // Without a code the learner stays anonymous, but one browser's statements still belong together.
  const actor: XapiAgent = { objectType: 'Agent', account: { homePage: assignment?.xapiHomePage ?? XAPI_BASE, name: owner.learnerId } };
  const label = assignmentLabel(assignment);
  const grouping = [activities.app(), ...(label.id && label.title ? [activities.assignment(label.id, label.title)] : [])];
  const language = assignment?.locale ?? progress.settings.locale;
  const statements: Omit<XapiStatement, 'id'>[] = [];
  const add = (verb: XapiVerb, object: XapiActivity, timestamp: string, result?: XapiResult, level?: string) =>
    statements.push({
      actor,
      verb,
      object,
      ...(result ? { result } : {}),
      context: {
        registration: input.attemptId,
        platform: 'Ray Tracer Quest',
        language,
        contextActivities: { ...(level ? { parent: [activities.level(level)] } : {}), grouping },
        extensions: {
          [EXTENSIONS.appVersion]: input.appVersion,
          ...(input.utcOffsetMin === undefined ? {} : { [EXTENSIONS.utcOffsetMin]: String(input.utcOffsetMin) }),
        },
      },
      timestamp,
    });

  const openedAt = new Map<string, number>();
  for (const event of events) {
    const at = isoAt(startedAt, event.t);
    eventStatement(event, at, openedAt, add, input.optionText ?? NO_OPTION_TEXTS);
  }
  for (const attempt of readLog(progress.log).attempts) {
    if (attempt.how === null || attempt.completedAt === null) continue;
    const result: XapiResult = {
      completion: attempt.how !== 'skipped',
      // A quiz answered wrong is completed, not succeeded.
      success: attempt.how === 'done' && attempt.quizCorrect !== false,
      score: { raw: attempt.points, min: 0 },
      duration: isoDuration(attempt.durationMs),
      extensions: {
        [EXTENSIONS.how]: attempt.how,
        [EXTENSIONS.activeMs]: attempt.activeMs,
        [EXTENSIONS.hintsOffered]: attempt.hintsOffered,
        [EXTENSIONS.hintsOpened]: hintsOpened(attempt),
        [EXTENSIONS.explanationOpens]: attempt.explanationOpens,
        ...challengeExtensions(attempt.challenge),
        ...codeExtensions(attempt.code),
      },
    };
    add(attempt.how === 'skipped' ? VERBS.skipped : VERBS.completed, activities.task(attempt.level, attempt.task), attempt.completedAt, result, attempt.level);
  }
  if (input.survey) {
    const { survey, submittedAt, answers } = input.survey;
    for (const [question, answer] of Object.entries(answers))
      add(VERBS.answered, activities.question(survey, question), submittedAt, { response: String(answer) });
    add(VERBS.completed, activities.survey(survey), submittedAt, { completion: true });
  }
  // Stable: statements of the same moment keep the log's order.
  statements.sort((a, b) => Date.parse(a.timestamp) - Date.parse(b.timestamp));
  return statements.map((statement, index) => ({ id: statementId(statement, index), ...statement }));
}

type Add = (verb: XapiVerb, object: XapiActivity, timestamp: string, result?: XapiResult, level?: string) => void;

/** The statement of one logged event, if it has one (task completions come from the attempts). */
function eventStatement(event: LoggedEvent, at: string, openedAt: Map<string, number>, add: Add, optionText: OptionText): void {
  switch (event.type) {
    case 'session.started':
      return add(VERBS.launched, activities.app(), event.at);
    case 'level.opened':
      openedAt.set(event.level, event.t);
      return add(VERBS.attempted, activities.level(event.level), at);
    case 'level.closed':
      return add(VERBS.exited, activities.level(event.level), at, { duration: isoDuration(event.t - (openedAt.get(event.level) ?? event.t)) });
    case 'level.passed':
      return add(VERBS.passed, activities.level(event.level), at, {
        success: true,
        completion: true,
        duration: isoDuration(event.t - (openedAt.get(event.level) ?? event.t)),
      });
    case 'quiz.answered': {
      // A choice interaction's response is the chosen option's id (xAPI 1.0.3 §4.1.4.1, "choice"); an estimate's, the number.
      const result: XapiResult =
        event.choice === undefined
          ? { success: event.correct, response: String(event.value) }
          : {
              success: event.correct,
              response: optionId(event.choice),
              extensions: { [EXTENSIONS.choiceText]: optionText(event.level, event.task, event.choice) },
            };
      return add(VERBS.answered, activities.task(event.level, event.task), at, result, event.level);
    }
    case 'hint.shown':
      return add(
        VERBS.experienced,
        activities.hint(event.level, event.task, event.step),
        at,
        { extensions: { [EXTENSIONS.trigger]: event.trigger } },
        event.level,
      );
    case 'explanation.expanded':
      return add(VERBS.experienced, activities.explanation(event.level, event.task), at, undefined, event.level);
    case 'badge.earned':
      return add(VERBS.earned, activities.badge(event.badge), at);
    default:
      return;
  }
}

/** A UUID (version 8: made by us) from the statement's content and place: the same file always gives the same ids. */
function statementId(statement: Omit<XapiStatement, 'id'>, index: number): string {
  const text = `${index}|${statement.context.registration}|${statement.actor.account.name}|${statement.verb.id}|${statement.object.id}|${statement.timestamp}`;
  const hex = [0x811c9dc5, 0x01000193, 0x2545f491, 0x9e3779b9].map((seed) => fnv1a(text, seed).toString(16).padStart(8, '0')).join('');
  const variant = ((parseInt(hex[16], 16) & 0x3) | 0x8).toString(16);
  return `${hex.slice(0, 8)}-${hex.slice(8, 12)}-8${hex.slice(13, 16)}-${variant}${hex.slice(17, 20)}-${hex.slice(20, 32)}`;
}

/** A challenge's tries as the CSV's challenge_* columns (xAPI extensions hold numbers and text). */
function challengeExtensions(tries: ChallengeTries | undefined): Record<string, string | number> {
  if (!tries) return {};
  return {
    [EXTENSIONS.challengeRenders]: tries.renders,
    [EXTENSIONS.challengeChanges]: tries.changes,
    [EXTENSIONS.challengeRays]: tries.rays,
    [EXTENSIONS.challengeScores]: tries.scores.join(' '),
    ...(tries.stars === null ? {} : { [EXTENSIONS.challengeStars]: tries.stars }),
  };
}

/** A code lab's runs as the CSV's code_* columns (a run with no failing case is `-`). */
function codeExtensions(runs: CodeRuns | undefined): Record<string, string | number | boolean> {
  if (!runs) return {};
  return {
    [EXTENSIONS.codeRuns]: runs.runs,
    [EXTENSIONS.codePassed]: runs.passed,
    [EXTENSIONS.codeTotal]: runs.total,
    [EXTENSIONS.codeFailing]: runs.failing.map((kind) => kind ?? '-').join(' '),
    [EXTENSIONS.codeSolved]: runs.solved,
  };
}
