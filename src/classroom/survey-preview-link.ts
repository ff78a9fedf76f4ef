/**
 * The teacher's preview of a survey (`#/survey/<id>/<question>,<question>…`, linked from the
 * teacher page): the survey as their assignment asks it, only the questions they chose.
 * Without the list (`#/survey/<id>`, an older bookmark) it shows every question.
 */
export const SURVEY_PREVIEW = '#/survey/';

export function surveyPreviewHash(surveyId: string, questions: readonly string[]): string {
  return `${SURVEY_PREVIEW}${encodeURIComponent(surveyId)}/${questions.map(encodeURIComponent).join(',')}`;
}

/** The survey and its questions in a preview's address; `questions` is null when it names none. */
export function readSurveyPreview(route: string): { surveyId: string; questions: string[] | null } {
  const [surveyId = '', list] = route.slice(SURVEY_PREVIEW.length).split('/');
  const questions = list
    ? list
        .split(',')
        .filter((id) => id !== '')
        .map(decodeURIComponent)
    : [];
  return { surveyId: decodeURIComponent(surveyId), questions: questions.length > 0 ? questions : null };
}
