import { describe, expect, it } from 'vitest';
import { checkAnswers, cleanAnswers } from '../../src/classroom/survey-answers.ts';
import { parseSurvey, type Survey } from '../../src/classroom/survey-schema.ts';
import { SurveyStore, surveyKey } from '../../src/classroom/survey-store.ts';
import { surveyById, SURVEY_IDS } from '../../src/classroom/surveys.ts';
import defaultFile from '../../src/classroom/surveys/default.survey.json';
import { MemoryStorage } from '../../src/quest/progress-store.ts';

describe('survey files', () => {
  it('every shipped survey is valid', () => {
    expect(parseSurvey(defaultFile)).toMatchObject({ ok: true });
    expect(SURVEY_IDS).toEqual(['default']);
  });

  it('the default survey follows the study: context, five learning scales, rays, why, ease, feedback', () => {
    const survey = surveyById('default') as Survey;
    const byId = new Map(survey.questions.map((q) => [q.id, q]));
    expect(byId.get('education')?.type).toBe('choice');
    expect(byId.get('computer-skill')).toMatchObject({ type: 'scale', min: 1, max: 10 });
    expect(byId.get('prior-knowledge')).toMatchObject({ type: 'scale', min: 1, max: 5 });
    expect(byId.get('minutes')).toMatchObject({ type: 'number', required: true });
    expect(byId.get('age')).toMatchObject({ type: 'number', required: false });
    const learning = survey.questions.filter((q) => q.id.startsWith('learned-'));
    expect(learning).toHaveLength(5);
    for (const q of learning) expect(q).toMatchObject({ type: 'scale', min: 1, max: 5, minLabel: { en: 'Did not help' }, maxLabel: { en: 'Helped a lot' } });
    expect(byId.get('ray-views')).toMatchObject({ type: 'scale', min: 1, max: 5 });
    expect(byId.get('ray-views-remark')?.type).toBe('text');
    expect(byId.get('why-understood')?.type).toBe('text');
    const ease = byId.get('ease');
    expect(ease?.type === 'choice' && ease.options.map((o) => o.id)).toEqual(['too-simple', 'about-right', 'too-complex']);
    expect(byId.get('feedback')).toMatchObject({ type: 'text', required: false });
    // Every text has its Dutch version.
    expect(JSON.stringify(defaultFile).match(/"en":/g)?.length).toBe(JSON.stringify(defaultFile).match(/"nl":/g)?.length);
  });

  it('explains what is wrong in a broken survey file', () => {
    const broken = { version: 1, id: 'x', title: 'T', questions: [{ id: 'a', type: 'scale', text: 'Q', min: 5, max: 1, minLabel: 'lo', maxLabel: 'hi' }, { id: 'a', type: 'text', text: 'Q' }] };
    const result = parseSurvey(broken);
    expect(result).toEqual({ ok: false, errors: ['questions[0].max: max must be above min, with at most 11 steps', 'questions[1].id: "a" is used more than once'] });
  });
});

describe('survey limits', () => {
  it('refuses a file of 2,000 copies of one question by its count, not by comparing every pair', () => {
    const question = { id: 'q', type: 'text', text: 'Why?' };
    const result = parseSurvey({ version: 1, id: 'big', title: 'Big', questions: Array.from({ length: 2000 }, () => question) });
    expect(result).toMatchObject({ ok: false, errors: expect.arrayContaining(['questions: must have at most 100 items, got a list of 2000 items']) });
  });

  it('refuses texts over 5,000 characters and ids over 64', () => {
    const result = parseSurvey({ version: 1, id: 'x'.repeat(65), title: 'y'.repeat(5001), questions: [{ id: 'q', type: 'text', text: 'Why?' }] });
    expect(result).toEqual({ ok: false, errors: ['id: must be at most 64 characters long', 'title: must be at most 5000 characters long'] });
  });
});

describe('survey answers', () => {
  const survey: Survey = {
    version: 1,
    id: 't',
    title: 'T',
    questions: [
      { id: 'pick', type: 'choice', text: 'Pick', required: true, options: [{ id: 'a', text: 'A' }, { id: 'b', text: 'B' }] },
      { id: 'rate', type: 'scale', text: 'Rate', required: true, min: 1, max: 5, minLabel: 'lo', maxLabel: 'hi' },
      { id: 'age', type: 'number', text: 'Age', required: false, min: 6, max: 120, integer: true },
      { id: 'say', type: 'text', text: 'Say', required: false, maxLength: 5 },
    ],
  };

  it('accepts complete answers and leaves optional ones open', () => {
    expect(checkAnswers(survey, { pick: 'a', rate: 3 })).toEqual({});
  });

  it('names each problem', () => {
    expect(checkAnswers(survey, { pick: 'c', age: 3.5, say: 'too long' })).toEqual({
      pick: { kind: 'unknown-option' },
      rate: { kind: 'required' },
      age: { kind: 'not-whole' },
      say: { kind: 'too-long', max: 5 },
    });
    expect(checkAnswers(survey, { pick: ' ', rate: 9, age: 200 })).toEqual({
      pick: { kind: 'required' },
      rate: { kind: 'out-of-range', min: 1, max: 5 },
      age: { kind: 'out-of-range', min: 6, max: 120 },
    });
  });

  it('keeps only the survey\'s own answers, trimmed', () => {
    expect(cleanAnswers(survey, { pick: 'a', rate: 2, say: '  hi ', other: 'x', age: '' as unknown as number })).toEqual({ pick: 'a', rate: 2, say: 'hi' });
  });
});

describe('survey store', () => {
  const submission = { survey: 'default', submittedAt: '2025-03-04T10:00:00.000Z', answers: { rate: 3, say: 'hi' } };

  it('reads the answers kept next to the progress, apart per progress key', () => {
    const storage = new MemoryStorage();
    expect(new SurveyStore(storage, 'rtq.progress.assignment.abc').load()).toBeNull();
    storage.setItem(surveyKey('rtq.progress.assignment.abc'), JSON.stringify(submission));
    expect(surveyKey('rtq.progress.assignment.abc')).toBe('rtq.progress.assignment.abc.survey');
    expect(new SurveyStore(storage, 'rtq.progress.assignment.abc').load()).toEqual(submission);
    expect(new SurveyStore(storage, 'rtq.progress').load()).toBeNull();
  });

  it('reads damaged values as absent', () => {
    const storage = new MemoryStorage();
    storage.setItem(surveyKey('k'), '{"survey": 3');
    expect(new SurveyStore(storage, 'k').load()).toBeNull();
  });
});
