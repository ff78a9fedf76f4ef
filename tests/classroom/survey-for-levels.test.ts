import { describe, expect, it } from 'vitest';
import { readFileSync } from 'node:fs';
import { ownSurveyChoice, surveyAsked, surveyForLevels } from '../../src/classroom/survey-for-levels.ts';
import { surveyById } from '../../src/classroom/surveys.ts';

const survey = surveyById('default')!;
const ids = (levels: string[] | null) => surveyForLevels(survey, levels).questions.map((question) => question.id);
const index = JSON.parse(readFileSync(new URL('../../levels/index.json', import.meta.url), 'utf8')) as unknown;

describe('the survey an assignment asks', () => {
  it('leaves out questions on ideas the chosen levels do not teach', () => {
    const lesson = ids(['01-introduction', '02-rays-from-the-camera', '03-shading', '04-shadows']);
    expect(lesson).not.toContain('learned-attenuation');
    expect(lesson).not.toContain('learned-soft-shadows');
    expect(lesson).not.toContain('learned-supersampling');
    expect(lesson).not.toContain('learned-light-sources');
    expect(lesson).toContain('learned-ray-tracing');
    expect(ids(['09-attenuation', '10-area-lights'])).toEqual(expect.arrayContaining(['learned-attenuation', 'learned-soft-shadows', 'learned-light-sources']));
    expect(ids(null)).toEqual(survey.questions.map((question) => question.id));
  });

  it("asks the teacher's own choice over the default", () => {
    const lesson = ['01-introduction', '04-shadows'];
    const asked = (choice: Record<string, boolean>) => surveyAsked(survey, lesson, choice).questions.map((question) => question.id);
    const chosen = asked({ 'learned-soft-shadows': true, age: false });
    expect(chosen).toContain('learned-soft-shadows');
    expect(chosen).not.toContain('age');
    expect(chosen).not.toContain('learned-attenuation');
    // In the survey's order, whatever the order of the choice.
    expect(chosen).toEqual(survey.questions.map((question) => question.id).filter((id) => chosen.includes(id)));
    // A question the survey does not have changes nothing.
    expect(asked({ 'not-a-question': true })).toEqual(ids(lesson));
    // Every question off (only a hand-edited link does that): the default's questions rather than none.
    expect(asked(Object.fromEntries(survey.questions.map((question) => [question.id, false])))).toEqual(ids(lesson));
  });

  it("keeps of the teacher's choice only what differs from the default", () => {
    const lesson = ['01-introduction', '09-attenuation'];
    expect(
      ownSurveyChoice(survey, lesson, {
        'learned-attenuation': true,
        'learned-soft-shadows': false,
        'learned-supersampling': true,
        age: false,
        'not-a-question': true,
      }),
    ).toEqual({
      'learned-supersampling': true,
      age: false,
    });
    expect(ownSurveyChoice(survey, lesson, { 'learned-attenuation': true })).toBeUndefined();
    expect(ownSurveyChoice(survey, lesson, undefined)).toBeUndefined();
  });

  it('names only levels the game has', () => {
    const text = JSON.stringify(index);
    for (const question of survey.questions) for (const level of question.levels ?? []) expect(text, `${question.id}: ${level}`).toContain(`"${level}`);
  });

  it("asks for the learner's current education with the Dutch school types", () => {
    const education = survey.questions.find((question) => question.id === 'education');
    expect(education?.type === 'choice' && education.options.map((option) => option.id)).toEqual(['vmbo', 'havo', 'vwo', 'mbo', 'hbo', 'wo', 'other']);
    expect(education?.text).toMatchObject({ nl: 'Op welke school of opleiding zit je nu?' });
  });
});
