import { msg } from '@lit/localize';
import type { Assignment } from './assignment.ts';

/**
 * The information a pupil reads before starting an assignment that asks for a participant
 * code (a study): the teacher's own text, or this default. The default says only what is
 * true of this app (docs/classroom.md, "Data protection"): what the event log and the survey
 * hold (the time zone too: export-context.ts), that nothing leaves the browser until the pupil
 * hands it in or the learning platform that launched the game records it (SCORM), that taking part is
 * voluntary, and how to withdraw (the Menu's "Withdraw and delete my data", rt-withdraw.ts).
 * Written for a pupil of 12 to 18, as the AVG/GDPR asks of information for children
 * (art. 12(1): "clear and plain language … addressed specifically to a child").
 */
export function consentText(assignment: Assignment | null): string {
  return assignment?.consent ?? defaultConsentText();
}

export function defaultConsentText(): string {
  return [
    msg(
      'What is recorded: what you do in the game (tasks, hints, answers and how long they took) and your answers to any questions before or after it (the survey may ask your age and school), under the participant code your teacher gave you. Not recorded: your name, your e-mail address, or anything about your computer except its time zone.',
    ),
    msg(
      "Who sees it: nobody, until you hand in your results. Then your teacher sees them (and, in a study, the researchers they work with), under your code. The game sends nothing anywhere by itself, except to your school's learning platform when you play it there: the platform keeps your results as you play, under your name.",
    ),
    msg(
      'Taking part is voluntary. You can stop at any time: Menu › Withdraw and delete my data deletes what this browser kept, and your teacher deletes what you handed in.',
    ),
  ].join('\n\n');
}
