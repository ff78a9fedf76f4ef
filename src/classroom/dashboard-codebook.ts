import { localize, type Locale } from '../quest/localized-text.ts';
import { ATTEMPT_COLUMN_MEANINGS } from './attempt-column-meanings.ts';
import { ATTEMPT_COLUMNS, SURVEY_PREFIX } from './attempt-columns.ts';
import { LEARNER_LEVEL_COLUMNS } from './dashboard-learner-levels.ts';
import { optionId, type ChoiceQuestion } from './quiz-options.ts';
import type { Survey, SurveyQuestion } from './survey-schema.ts';

/**
 * The codebook the dashboard downloads with the data (Markdown: readable as it is, and
 * tables a word processor or a Markdown viewer lays out): every column of the CSV export and
 * of the per-learner × level table with its meaning and unit, every quiz question with its
 * options' ids and texts, every survey question with its options or scale ends. Question
 * and option texts are in `locale`, the dashboard's language; the rest is in English, like
 * the column names.
 */

/** A table cell: a pipe or a line break would end the cell, and `<…>` would be read as an HTML tag. */
const cell = (text: string) => text.replace(/([|<])/g, '\\$1').replace(/\s*\n\s*/g, ' ');
const table = (header: string[], rows: string[][]) =>
  [`| ${header.join(' | ')} |`, `| ${header.map(() => '---').join(' | ')} |`, ...rows.map((row) => `| ${row.map(cell).join(' | ')} |`)].join('\n');

export interface CodebookInput {
  appVersion: string;
  /** ISO 8601, when the codebook was made. */
  madeAt: string;
  locale: Locale;
  questions: readonly ChoiceQuestion[];
  surveys: readonly Survey[];
}

export function codebookMarkdown({ appVersion, madeAt, locale, questions, surveys }: CodebookInput): string {
  const attemptRows = ATTEMPT_COLUMNS.map((column) => {
    const known = ATTEMPT_COLUMN_MEANINGS[column.name];
    return [`\`${column.name}\``, known?.meaning ?? '', known?.unit ?? ''];
  });
  const sections = [
    `# Codebook: Ray Tracer Quest ${appVersion}`,
    `Made ${madeAt} by the class dashboard. Times are ISO 8601 in UTC; \`utc_offset_min\` turns them into the learner's clock time.`,
    '## CSV export and combined CSV: one row per task attempt',
    table(
      ['column', 'meaning', 'unit'],
      [
        ...attemptRows,
        [
          `\`${SURVEY_PREFIX}<question>\``,
          "the answer to that survey question (see Survey below). A learner's own CSV has a column only for the questions their assignment asked; in the combined CSV an empty cell is a question left open or not asked of that learner",
          'per question',
        ],
        ['`file`', 'combined CSV only: the file the row came from', 'text'],
      ],
    ),
    '## Per learner and level: one row per learner and level they opened',
    table(
      ['column', 'meaning', 'unit'],
      LEARNER_LEVEL_COLUMNS.map((column) => [`\`${column.name}\``, column.meaning, column.unit]),
    ),
    '## Quiz questions',
    'A quiz option is named by the letter of its place in the level file (`quiz_choice`); learners saw the options in a shuffled order of their own.',
    ...questions.map((question) =>
      [
        `### ${question.level} / ${question.task}`,
        question.question,
        table(
          ['id', question.pictures ? 'option (a picture the tracer renders)' : 'option', 'right'],
          question.options.map((text, position) => [
            optionId(position),
            question.pictures ? `picture ${optionId(position)}` : text,
            position === question.answer ? 'yes' : '',
          ]),
        ),
      ].join('\n\n'),
    ),
    ...surveys.flatMap((survey) => [
      `## Survey: ${localize(survey.title, locale)} (\`${survey.id}\`)`,
      ...survey.questions.map((question) => surveyQuestionText(question, locale)),
    ]),
  ];
  return `${sections.join('\n\n')}\n`;
}

function surveyQuestionText(question: SurveyQuestion, locale: Locale): string {
  const asked = question.levels
    ? `\n\nAsked by default only in assignments with one of the levels ${question.levels.map((level) => `\`${level}\``).join(', ')}; the teacher may tick it on or off (the assignment's \`surveyQuestions\`).`
    : '';
  const heading = `### \`${SURVEY_PREFIX}${question.id}\` (${question.type}${question.required ? ', required' : ', optional'})\n\n${localize(question.text, locale)}${asked}`;
  switch (question.type) {
    case 'choice':
      return `${heading}\n\n${table(
        ['id', 'option'],
        question.options.map((option) => [option.id, localize(option.text, locale)]),
      )}`;
    case 'scale':
      return `${heading}\n\nA whole number from ${question.min} (${localize(question.minLabel, locale)}) to ${question.max} (${localize(question.maxLabel, locale)}).`;
    case 'number': {
      const range = [question.min === undefined ? '' : `at least ${question.min}`, question.max === undefined ? '' : `at most ${question.max}`]
        .filter(Boolean)
        .join(', ');
      return `${heading}\n\nA ${question.integer ? 'whole ' : ''}number${range ? `, ${range}` : ''}.`;
    }
    case 'text':
      return `${heading}\n\nFree text typed by the learner (at most ${question.maxLength} characters).`;
    default: {
      const never: never = question;
      return never;
    }
  }
}
