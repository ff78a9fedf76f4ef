import type { Badge } from '../quest/badges.ts';

/**
 * The IRIs our xAPI statements use. Verbs come from ADL's list (http://adlnet.gov/expapi/verbs/)
 * where it has one, and from the xAPI registry's (http://id.tincanapi.com/verb/) for
 * "skipped" and "earned", which ADL lacks. Activities live under one stable base, so that a
 * learning record store groups the same task of every class together.
 */

export const XAPI_BASE = 'https://raytracerquest.example';

const adl = (name: string) => ({ id: `http://adlnet.gov/expapi/verbs/${name}`, display: { 'en-US': name } });
const registry = (name: string) => ({ id: `http://id.tincanapi.com/verb/${name}`, display: { 'en-US': name } });

export const VERBS = {
  launched: adl('launched'),
  attempted: adl('attempted'),
  exited: adl('exited'),
  passed: adl('passed'),
  completed: adl('completed'),
  answered: adl('answered'),
  experienced: adl('experienced'),
  skipped: registry('skipped'),
  earned: registry('earned'),
} as const;

export type XapiVerb = (typeof VERBS)[keyof typeof VERBS];

const activityType = (name: string) => `http://adlnet.gov/expapi/activities/${name}`;

export interface XapiActivity {
  objectType: 'Activity';
  id: string;
  definition: { type: string; name: { 'en-US': string } };
}

function activity(path: string, type: string, name: string): XapiActivity {
  return { objectType: 'Activity', id: `${XAPI_BASE}/${path}`, definition: { type: activityType(type), name: { 'en-US': name } } };
}

export const activities = {
  app: (): XapiActivity => ({ ...activity('', 'simulation', 'Ray Tracer Quest'), id: XAPI_BASE }),
  assignment: (id: string, title: string) => activity(`assignments/${id}`, 'course', title),
  level: (level: string) => activity(`levels/${level}`, 'lesson', level),
  task: (level: string, task: string) => activity(`levels/${level}/tasks/${task}`, 'interaction', `${level}: ${task}`),
  hint: (level: string, task: string, step: string) => activity(`levels/${level}/tasks/${task}/hints/${step}`, 'media', `${step} hint for ${level}: ${task}`),
  explanation: (level: string, task: string | null) =>
    activity(task === null ? `levels/${level}/explanation` : `levels/${level}/tasks/${task}/explanation`, 'media', `explanation of ${task ?? level}`),
  badge: (badge: Badge) => {
    const parts = Object.values(badge).join('/');
    return activity(`badges/${parts}`, 'objective', parts);
  },
  survey: (survey: string) => activity(`surveys/${survey}`, 'assessment', `survey ${survey}`),
  question: (survey: string, question: string) => activity(`surveys/${survey}/questions/${question}`, 'question', question),
};

/**
 * Extensions carry what the spec's fields do not: how a task was completed, active time,
 * hints, explanations opened, the chosen option's text, the app's version and the device's
 * offset from UTC.
 */
export const EXTENSIONS = {
  how: `${XAPI_BASE}/extensions/how`,
  activeMs: `${XAPI_BASE}/extensions/active-ms`,
  hintsOffered: `${XAPI_BASE}/extensions/hints-offered`,
  hintsOpened: `${XAPI_BASE}/extensions/hints-opened`,
  trigger: `${XAPI_BASE}/extensions/trigger`,
  appVersion: `${XAPI_BASE}/extensions/app-version`,
  utcOffsetMin: `${XAPI_BASE}/extensions/utc-offset-min`,
  choiceText: `${XAPI_BASE}/extensions/choice-text`,
  explanationOpens: `${XAPI_BASE}/extensions/explanation-opens`,
  /** A challenge's tries, as the CSV's challenge_* columns (challenge-attempt.ts). */
  challengeRenders: `${XAPI_BASE}/extensions/challenge-renders`,
  challengeChanges: `${XAPI_BASE}/extensions/challenge-changes`,
  challengeRays: `${XAPI_BASE}/extensions/challenge-rays`,
  challengeScores: `${XAPI_BASE}/extensions/challenge-scores`,
  challengeStars: `${XAPI_BASE}/extensions/challenge-stars`,
  /** A code lab's runs, as the CSV's code_* columns (code-lab-attempt.ts). */
  codeRuns: `${XAPI_BASE}/extensions/code-runs`,
  codePassed: `${XAPI_BASE}/extensions/code-passed`,
  codeTotal: `${XAPI_BASE}/extensions/code-total`,
  codeFailing: `${XAPI_BASE}/extensions/code-failing`,
  codeSolved: `${XAPI_BASE}/extensions/code-solved`,
} as const;
