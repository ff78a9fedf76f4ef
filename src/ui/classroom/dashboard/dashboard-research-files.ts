import { loadBrowserCatalog } from '../../../app/level-catalog-browser.ts';
import { combinedCsv, surveyCsv } from '../../../classroom/dashboard-class.ts';
import { codebookMarkdown } from '../../../classroom/dashboard-codebook.ts';
import { researchCsv } from '../../../classroom/research-export.ts';
import { learnerLevelCsv } from '../../../classroom/dashboard-learner-levels.ts';
import type { ClassLearner } from '../../../classroom/dashboard-learners.ts';
import type { LevelSummary } from '../../../classroom/dashboard-summary.ts';
import { APP_VERSION } from '../../../classroom/export-context.ts';
import { choiceQuestions, optionTexts, type OptionText } from '../../../classroom/quiz-options.ts';
import { SURVEY_IDS, surveyById } from '../../../classroom/surveys.ts';
import type { Locale } from '../../../quest/localized-text.ts';
import { playableLevels } from '../../../quest/level-index.ts';
import { downloadText } from '../../../util/download-file.ts';

export type ClassCsvKind = 'class' | 'survey' | 'research';

/**
 * The dashboard's files for a researcher, besides the combined CSV: the per-learner × level
 * table and the codebook, and the quiz questions (from the level files, in the page's
 * language) that the quiz results and the option texts come from.
 */
export const researchDownloads = {
  /**
   * The combined CSV of every learner shown, their survey CSV, or the research CSV (times from
   * the start, no device id; free text only when asked for, and marked).
   */
  classCsv(kind: ClassCsvKind, learners: readonly ClassLearner[], locale: Locale, freeText: boolean): void {
    const optionText = this.optionText(locale);
    const text =
      kind === 'class'
        ? combinedCsv(learners, surveyById, optionText)
        : kind === 'survey'
          ? surveyCsv(learners, surveyById)
          : researchCsv(learners, surveyById, { freeText }, optionText);
    downloadText(`\uFEFF${text}`, `ray-tracer-quest-${kind}-${today()}.csv`, 'text/csv;charset=utf-8');
  },

  questions: (locale: Locale) => choiceQuestions(playableLevels(loadBrowserCatalog()), locale),

  optionText(locale: Locale): OptionText {
    return optionTexts(this.questions(locale));
  },

  learnerLevels(learners: readonly ClassLearner[], levels: readonly LevelSummary[]): void {
    const text = learnerLevelCsv(
      learners,
      levels.map((level) => level.level),
    );
    downloadText(`\uFEFF${text}`, `ray-tracer-quest-learner-levels-${today()}.csv`, 'text/csv;charset=utf-8');
  },

  codebook(locale: Locale): void {
    const surveys = SURVEY_IDS.flatMap((id) => surveyById(id) ?? []);
    const text = codebookMarkdown({ appVersion: APP_VERSION, madeAt: new Date().toISOString(), locale, questions: this.questions(locale), surveys });
    downloadText(text, `ray-tracer-quest-codebook-${today()}.md`, 'text/markdown;charset=utf-8');
  },
};

/** The local date, as the downloads' names have it. */
function today(): string {
  const now = new Date();
  return `${now.getFullYear()}-${String(now.getMonth() + 1).padStart(2, '0')}-${String(now.getDate()).padStart(2, '0')}`;
}
