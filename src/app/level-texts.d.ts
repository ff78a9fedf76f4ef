/** scripts/level-texts-plugin.ts: the level files (by name) in one language. */
declare module 'virtual:level-texts/*' {
  const texts: Record<string, string>;
  export default texts;
}
