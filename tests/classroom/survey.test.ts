import { describe, expect, it } from 'vitest';
import { checkAnswers, cleanAnswers } from '../../src/classroom/survey-answers.ts';
import { parseSurvey, type Survey } from '../../src/classroom/survey-schema.ts';
import { loadSurvey, readSurveyText, surveyKey } from '../../src/classroom/survey-store.ts';
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
    const broken = {
      version: 1,
      id: 'x',
      title: 'T',
      questions: [
        { id: 'a', type: 'scale', text: 'Q', min: 5, max: 1, minLabel: 'lo', maxLabel: 'hi' },
        { id: 'a', type: 'text', text: 'Q' },
      ],
    };
    const result = parseSurvey(broken);
    expect(result).toEqual({
      ok: false,
      errors: ['questions[0].max: max must be above min, with at most 11 steps', 'questions[1].id: "a" is used more than once'],
    });
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
      {
        id: 'pick',
        type: 'choice',
        text: 'Pick',
        required: true,
        options: [
          { id: 'a', text: 'A' },
          { id: 'b', text: 'B' },
        ],
      },
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

  it("keeps only the survey's own answers, trimmed", () => {
    expect(cleanAnswers(survey, { pick: 'a', rate: 2, say: '  hi ', other: 'x', age: '' as unknown as number })).toEqual({ pick: 'a', rate: 2, say: 'hi' });
  });
});

describe('survey store', () => {
  const submission = { survey: 'default', submittedAt: '2025-03-04T10:00:00.000Z', answers: { rate: 3, say: 'hi' } };
  const wallMs = Date.parse('2025-03-05T08:00:00.000Z');
  const backupKey = (key: string) => `${surveyKey(key)}.backup.2025-03-05T08:00:00.000Z`;

  it('reads the answers kept next to the progress, apart per progress key', () => {
    const storage = new MemoryStorage();
    expect(loadSurvey(storage, 'rtq.progress.assignment.abc', wallMs)).toEqual({ submission: null, damage: null });
    storage.setItem(surveyKey('rtq.progress.assignment.abc'), JSON.stringify(submission));
    expect(surveyKey('rtq.progress.assignment.abc')).toBe('rtq.progress.assignment.abc.survey');
    expect(loadSurvey(storage, 'rtq.progress.assignment.abc', wallMs)).toEqual({ submission, damage: null });
    expect(loadSurvey(storage, 'rtq.progress', wallMs).submission).toBeNull();
    expect(storage.length).toBe(1); // nothing backed up
  });

  it('keeps a damaged record exactly as it was, and names what could not be read', () => {
    const storage = new MemoryStorage();
    const raw = '{"survey": 3';
    storage.setItem(surveyKey('k'), raw);
    expect(loadSurvey(storage, 'k', wallMs)).toEqual({
      submission: null,
      damage: { lost: ['survey', 'submittedAt'], cut: true, raw, backupKey: backupKey('k') },
    });
    expect(storage.getItem(backupKey('k'))).toBe(raw);
  });

  it('leaves out one bad answer and keeps the others', () => {
    const storage = new MemoryStorage();
    const raw = JSON.stringify({ ...submission, answers: { rate: 3, say: 'hi', pick: { id: 'a' }, age: null } });
    storage.setItem(surveyKey('k'), raw);
    const loaded = loadSurvey(storage, 'k', wallMs);
    expect(loaded.submission).toEqual(submission);
    expect(loaded.damage).toMatchObject({ lost: ['answers.pick', 'answers.age'], cut: false, backupKey: backupKey('k') });
  });

  it('reads the answers before the cut of a record cut short', () => {
    const whole = JSON.stringify({ ...submission, answers: { rate: 3, say: 'hi "there", you', age: 16, pick: 'b' } });
    const cut = whole.slice(0, whole.indexOf('16') + 1); // "age": 1 — a number that may go on is not taken
    expect(readSurveyText(cut)).toEqual({
      submission: { ...submission, answers: { rate: 3, say: 'hi "there", you' } },
      damaged: true,
      lost: [],
      cut: true,
    });
    expect(readSurveyText(whole.slice(0, -1)).submission?.answers).toEqual({ rate: 3, say: 'hi "there", you', age: 16, pick: 'b' });
  });

  it('asks again when the survey or its time cannot be read', () => {
    expect(readSurveyText(JSON.stringify({ ...submission, submittedAt: 'yesterday' }))).toMatchObject({
      submission: null,
      damaged: true,
      lost: ['submittedAt'],
    });
    expect(readSurveyText(JSON.stringify({ ...submission, survey: '' }))).toMatchObject({ submission: null, lost: ['survey'] });
    expect(readSurveyText(JSON.stringify({ ...submission, answers: [1] }))).toMatchObject({ submission: { answers: {} }, lost: ['answers'] });
    expect(readSurveyText('null')).toMatchObject({ submission: null, damaged: true });
  });

  it('never writes a backup over an older one, and holds the text when there is no room', () => {
    const storage = new MemoryStorage();
    storage.setItem(surveyKey('k'), 'garbage');
    storage.setItem(backupKey('k'), 'older');
    expect(loadSurvey(storage, 'k', wallMs).damage).toMatchObject({ raw: 'garbage', backupKey: null });
    expect(storage.getItem(backupKey('k'))).toBe('older');
    expect(storage.getItem(surveyKey('k'))).toBe('garbage');
  });
});
