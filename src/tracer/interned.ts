/**
 * `value` as the string constant of this program that spells it: `constants[value]`, a
 * table from each name to itself, or `value` when it names none.
 *
 * The tracer's hottest code compares kinds (a light's type, a shape's kind, the sample
 * pattern) with string constants. V8 compares two internalized strings by their address,
 * and the constants in the source are internalized, but a string that came through
 * postMessage (the scene a render worker receives, a structured clone) is a fresh copy, so
 * every comparison with it compares characters in a call. The reference render in a worker
 * took about 5 % longer than the same scene parsed on the worker's own thread, until the
 * tracer kept these constants instead.
 */
export function interned<T extends string>(value: T, constants: { readonly [K in T]: K }): T {
  return Object.hasOwn(constants, value) ? constants[value] : value;
}
