/**
 * `value` as the string constant of this program that spells it: `constants[value]`, a
 * table from each name to itself, or `value` when it names none.
 *
 * The tracer's hottest code compares kinds (a light's type, a shape's kind, the sample
 * pattern) with string constants; a string that came through postMessage (the scene a
 * render worker receives) is a copy, not the constant: docs/performance.md, "Internalized
 * strings".
 */
export function interned<T extends string>(value: T, constants: { readonly [K in T]: K }): T {
  return Object.hasOwn(constants, value) ? constants[value] : value;
}
