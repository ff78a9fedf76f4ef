import { msg, str } from '@lit/localize';

// How many learners answered a survey: whole sentences for one and for more, since the Dutch
// verb agrees with the count ("1 leerling heeft", "3 leerlingen hebben"; src/i18n/counted.ts).

export function respondentsText(respondents: number): string {
  return respondents === 1 ? msg('1 student answered.') : msg(str`${respondents} students answered.`);
}

/** A survey this version does not know (`id`): its answers are counted, not shown. */
export function unknownSurveyText(respondents: number, id: string): string {
  return respondents === 1
    ? msg(str`1 student answered a survey this version of the app does not know ("${id}"); the answers are in the files but not shown here.`)
    : msg(str`${respondents} students answered a survey this version of the app does not know ("${id}"); their answers are in the files but not shown here.`);
}
