import { describe, expect, it } from 'vitest';
import { readSurveyPreview, surveyPreviewHash } from '../../src/classroom/survey-preview-link.ts';

describe('survey preview link', () => {
  it('carries the chosen questions there and back', () => {
    const hash = surveyPreviewHash('default', ['education', 'minutes']);
    expect(hash).toBe('#/survey/default/education,minutes');
    expect(readSurveyPreview(hash)).toEqual({ surveyId: 'default', questions: ['education', 'minutes'] });
  });

  it('reads an older link without questions as the whole survey', () => {
    expect(readSurveyPreview('#/survey/default')).toEqual({ surveyId: 'default', questions: null });
    expect(readSurveyPreview('#/survey/default/')).toEqual({ surveyId: 'default', questions: null });
  });
});
