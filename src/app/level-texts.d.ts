/** scripts/level-texts-plugin.ts: the level files (by name) in one language. */
declare module 'virtual:level-texts/*' {
  const texts: Record<string, string>;
  export default texts;
}

/** scripts/level-texts-plugin.ts: the levels' "Explain more" texts in one language, by their keys. */
declare module 'virtual:level-more/*' {
  const texts: Record<string, string>;
  export default texts;
}
