import type { Assignment } from '../../src/classroom/assignment.ts';
import { buildExport, type QuestExport } from '../../src/classroom/export-json.ts';
import type { SurveyAnswers } from '../../src/classroom/survey-answers.ts';
import type { LoggedEvent, QuestEvent } from '../../src/quest/event-log.ts';
import { newProgress } from '../../src/quest/progress.ts';

/**
 * A simulated class for the dashboard's tests: each learner plays levels 1 and 2 of a
 * teacher's assignment with plausible times, hints, "show me", a hidden tab now and then,
 * some leave level 2 unfinished, most answer the default survey. Seeded, so every run makes
 * the same files.
 */

export const CLASS_ASSIGNMENT: Assignment = {
  version: 1,
  title: 'Ray tracing, lesson 1',
  levels: ['01-introduction', '02-rays-from-the-camera'],
  requiredTasks: {},
  otherLevels: 'hidden',
  locale: 'en',
  askParticipantCode: true,
  survey: 'default',
};

const LEVELS = [
  { id: '01-introduction', tasks: ['orbit', 'zoom', 'select-ball', 'color-ball'], optional: 'pan' },
  { id: '02-rays-from-the-camera', tasks: ['the-screen', 'count-rays', 'select-pixel', 'more-pixels'], optional: 'fly-to-camera' },
] as const;

/** mulberry32: a small seeded generator, good enough for test data. */
function random(seed: number): () => number {
  let state = seed >>> 0;
  return () => {
    state = (state + 0x6d2b79f5) >>> 0;
    let value = Math.imul(state ^ (state >>> 15), 1 | state);
    value = (value + Math.imul(value ^ (value >>> 7), 61 | value)) ^ value;
    return ((value ^ (value >>> 14)) >>> 0) / 4294967296;
  };
}

/** One learner's export, built by the app's own export code from a simulated log. */
export function simulatedExport(index: number, seed = 1): QuestExport {
  const rand = random(seed * 7919 + index);
  const between = (low: number, high: number) => Math.round(low + (high - low) * rand());
  const startedAt = new Date(Date.UTC(2026, 2, 9, 9, 0) + index * 1000).toISOString();
  const events: LoggedEvent[] = [];
  let t = 0;
  const log = (event: QuestEvent, after = 0) => {
    t += after;
    events.push({ ...event, t } as LoggedEvent);
  };
  log({ type: 'session.started', at: startedAt });
  for (const [levelIndex, level] of LEVELS.entries()) {
    // A few learners never get to level 2; of the others some leave it unfinished.
    if (levelIndex === 1 && rand() < 0.1) break;
    const leaveAt = levelIndex === 1 && rand() < 0.25 ? between(0, level.tasks.length - 1) : -1;
    log({ type: 'level.opened', level: level.id }, between(500, 3000));
    log({ type: 'task.shown', level: level.id, task: level.optional, mandatory: false, required: false });
    let passed = true;
    for (const [taskIndex, task] of level.tasks.entries()) {
      log({ type: 'task.shown', level: level.id, task, mandatory: true, required: true }, 200);
      if (taskIndex === leaveAt) {
        log({ type: 'level.closed', level: level.id }, between(5000, 60_000));
        passed = false;
        break;
      }
      const stuck = rand();
      if (stuck < 0.35) {
        // Half ask for the hint, half open the one offered after idle time.
        const offered = rand() >= 0.5;
        const after = between(10_000, 40_000);
        if (offered) log({ type: 'hint.offered', level: level.id, task, step: 'text' }, after);
        log({ type: 'hint.shown', level: level.id, task, step: 'text', trigger: offered ? 'offered' : 'asked' }, offered ? 0 : after);
      }
      if (stuck < 0.15) log({ type: 'hint.shown', level: level.id, task, step: 'guidance', trigger: 'asked' }, between(5000, 20_000));
      if (rand() < 0.1) {
        log({ type: 'tab.hidden' }, between(1000, 5000));
        log({ type: 'tab.visible' }, between(10_000, 90_000));
      }
      if (task === 'count-rays') log({ type: 'quiz.answered', level: level.id, task, choice: 1, correct: rand() < 0.6 }, between(5000, 20_000));
      const how = stuck < 0.06 ? 'shown' : 'done';
      if (how === 'shown') log({ type: 'hint.shown', level: level.id, task, step: 'show-me', trigger: 'asked' }, 2000);
      log({ type: 'task.completed', level: level.id, task, mandatory: true, required: true, how, points: how === 'done' ? 10 : 0 }, between(4000, 45_000));
    }
    if (!passed) break;
    if (rand() < 0.4) {
      // An optional task is timed from the learner's first move towards it.
      log({ type: 'task.started', level: level.id, task: level.optional }, between(1000, 5000));
      log({ type: 'task.completed', level: level.id, task: level.optional, mandatory: false, required: false, how: 'done', points: 5 }, between(3000, 20_000));
    }
    log({ type: 'level.passed', level: level.id });
    log({ type: 'level.closed', level: level.id }, 1000);
  }

  const clock = { monotonicMs: () => 0, wallMs: () => Date.parse(startedAt) };
  const progress = { ...newProgress(clock), log: { startedAt, events } };
  const answersSurvey = rand() < 0.8;
  return buildExport({
    progress,
    participant: `P${String(index + 1).padStart(2, '0')}`,
    installId: testUuid(seed * 10_000 + index),
    attemptId: testUuid(seed * 10_000 + index + 5_000),
    assignment: CLASS_ASSIGNMENT,
    survey: answersSurvey ? { survey: 'default', submittedAt: new Date(Date.parse(startedAt) + t).toISOString(), answers: surveyAnswers(rand) } : null,
    exportedAt: new Date(Date.parse(startedAt) + t + 1000).toISOString(),
    appVersion: '0.1.0',
  });
}

/** A fixed, valid version 4 UUID for test number `n`. */
export function testUuid(n: number): string {
  return `00000000-0000-4000-8000-${n.toString(16).padStart(12, '0')}`;
}

/** Answers to the default survey, leaning towards "helped". */
function surveyAnswers(rand: () => number): SurveyAnswers {
  const likert = () => Math.min(5, 1 + Math.floor(rand() * 3 + rand() * 3));
  return {
    education: rand() < 0.7 ? 'havo' : 'vwo',
    'computer-skill': 1 + Math.floor(rand() * 10),
    'prior-knowledge': 1 + Math.floor(rand() * 3),
    minutes: 20 + Math.floor(rand() * 40),
    'learned-ray-tracing': likert(),
    'learned-light-sources': likert(),
    'learned-attenuation': likert(),
    'learned-soft-shadows': likert(),
    'learned-supersampling': likert(),
    'ray-views': likert(),
    ease: rand() < 0.8 ? 'about-right' : 'too-complex',
    ...(rand() < 0.3 ? { feedback: 'More levels please, with "quotes", commas and =formulas' } : {}),
  };
}

/** The files of a class of `count` learners, named as the app names its downloads. */
export function simulatedClassFiles(count: number, seed = 1): { name: string; text: string }[] {
  return Array.from({ length: count }, (_, index) => {
    const file = simulatedExport(index, seed);
    return { name: `ray-tracer-quest-${file.participant}.json`, text: `${JSON.stringify(file, null, 2)}\n` };
  });
}
