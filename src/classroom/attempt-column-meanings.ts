/**
 * What each column of the CSV export (attempt-columns.ts) holds and in what unit, for the
 * codebook the dashboard downloads (dashboard-codebook.ts). docs/classroom.md says the
 * same at more length; tests/classroom/codebook.test.ts checks every column is here.
 */
export const ATTEMPT_COLUMN_MEANINGS: Readonly<Record<string, { meaning: string; unit: string }>> = {
  learner_id: { meaning: 'the learner: the participant code, or install:<install_id> without one', unit: 'text' },
  attempt_id: { meaning: "the playthrough's random id; every file of one playthrough has the same", unit: 'text (UUID)' },
  install_id: { meaning: "the browser's random id", unit: 'text (UUID)' },
  participant: { meaning: 'the participant code as typed, or empty when none was asked', unit: 'text' },
  assignment: { meaning: "the assignment's title, or empty in free play", unit: 'text' },
  assignment_id: { meaning: "the assignment's id (a hash of the assignment), or empty", unit: 'text (8 hex digits)' },
  class_code: { meaning: "the assignment's class code, or empty", unit: 'text' },
  level: { meaning: "the level's id", unit: 'text' },
  task: { meaning: "the task's id within the level", unit: 'text' },
  kind: { meaning: 'do (something in the lab), quiz (a prediction) or info (read, then Next)', unit: 'category' },
  mandatory: { meaning: 'whether the task had to be done to pass the level for this learner (never for an info step)', unit: 'true/false' },
  started_at: { meaning: 'when the attempt started (an optional task: at the first move towards it)', unit: 'ISO 8601 time, UTC' },
  completed_at: { meaning: 'when the attempt was completed; empty when it ended unfinished', unit: 'ISO 8601 time, UTC' },
  duration_ms: { meaning: 'completed_at − started_at; for an unfinished attempt up to when it ended', unit: 'milliseconds' },
  active_ms: { meaning: 'the part of duration_ms with the tab visible and the page open', unit: 'milliseconds' },
  how: { meaning: 'done (by the learner), shown ("Show me"), skipped (optional, left out), or empty when unfinished', unit: 'category' },
  hints_text: { meaning: 'text hints the learner opened during the attempt', unit: 'count' },
  hints_guidance: { meaning: '"show me where" rings the learner opened during the attempt', unit: 'count' },
  hints_offered: { meaning: 'hints offered after idle time during the attempt, opened or not', unit: 'count' },
  hints_opened: { meaning: 'hints_text + hints_guidance: the hints that count as used', unit: 'count' },
  shown_by_app: { meaning: '"Show me" completed the task (how = shown)', unit: 'true/false' },
  attempts: { meaning: "the attempt's number for this task (1, 2, …)", unit: 'count' },
  quiz_answers: { meaning: 'quiz answers given in the attempt', unit: 'count' },
  quiz_correct: { meaning: 'whether the quiz answer was right; empty when none was given', unit: 'true/false' },
  quiz_choice: { meaning: 'the option chosen, by the letter of its place in the level file (see the quiz questions below)', unit: 'option id (a, b, …)' },
  quiz_choice_text: { meaning: "the chosen option's text in the file's language; empty for a picture quiz", unit: 'text' },
  explanation_opens: { meaning: '"Explain more" opened for the task', unit: 'count' },
  points: { meaning: 'points earned (a wrong quiz answer earns none)', unit: 'points' },
  app_version: { meaning: 'the version of Ray Tracer Quest that wrote the file', unit: 'text (major.minor.patch)' },
  utc_offset_min: { meaning: "how far the device's clock was ahead of UTC at the download: local time = UTC time + this", unit: 'minutes' },
  survey: { meaning: 'the id of the survey the learner handed in, or empty', unit: 'text' },
};
