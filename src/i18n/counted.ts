import { msg, str } from '@lit/localize';

// A count said with its noun: "1 lamp", "3 lampen". English and Dutch both take the singular
// for exactly one and the plural for every other count, zero included ("0 lampen"), so each
// noun is two whole msg() phrases and a translator never builds a plural. A sentence whose
// verb agrees with the count ("1 leerling heeft", "3 leerlingen hebben") needs its own two
// msg() sentences instead.

export function objectsCounted(n: number): string {
  return n === 1 ? msg('1 object') : msg(str`${n} objects`);
}

export function lightsCounted(n: number): string {
  return n === 1 ? msg('1 light') : msg(str`${n} lights`);
}

export function studentsCounted(n: number): string {
  return n === 1 ? msg('1 student') : msg(str`${n} students`);
}

/** `shown`: the count as the panel writes it (with a thousands separator). */
export function bvhBoxesCounted(n: number, shown: string): string {
  return n === 1 ? msg('1 BVH box') : msg(str`${shown} BVH boxes`);
}

/** `shown`: the count as the panel writes it (with a thousands separator). */
export function trianglesCounted(n: number, shown: string): string {
  return n === 1 ? msg('1 triangle') : msg(str`${shown} triangles`);
}

export function answersCounted(n: number): string {
  return n === 1 ? msg('1 answer') : msg(str`${n} answers`);
}

export function pointsCounted(n: number): string {
  return n === 1 ? msg('1 point') : msg(str`${n} points`);
}
