/**
 * The mark a level text carries in the browser when its words load later: "Explain more"
 * texts are kept out of the first load (scripts/level-texts-plugin.ts) and stand in the level
 * as this prefix and a key; src/app/later-level-texts.ts finds the words by the key.
 */
export const LATER_TEXT_KEY = '@later:';
