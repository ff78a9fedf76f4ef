/**
 * Texts that arrive after the first screen: the Dutch messages of the parts that load later
 * (src/locales/nl-later.ts, split off by scripts/split-dutch-catalogue.ts) and the translated
 * reasons of a refused file (issue-text.ts). When either arrives, this event is sent on the
 * window, and every element renders again (src/ui/controls/localized-element.ts), so a text
 * shown in English for a moment is said in the learner's language.
 */
export const LATER_TEXTS_ARRIVED = 'rt-later-texts-arrived';
