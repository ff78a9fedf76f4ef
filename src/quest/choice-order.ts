/**
 * The order in which a learner sees a quiz's choices: a permutation fixed per learner and
 * quiz, so that the right answer's place cannot be learned from a classmate ("it's always the
 * third") or from the author's habit of putting it last, yet stays put across reloads.
 */

/** FNV-1a, 32 bits: a stable hash of the seed text. */
function hash(text: string): number {
  let h = 0x811c9dc5;
  for (let i = 0; i < text.length; i++) {
    h ^= text.charCodeAt(i);
    h = Math.imul(h, 0x01000193);
  }
  return h >>> 0;
}

/** mulberry32: a small generator of numbers in [0, 1), plenty for shuffling six choices. */
function generator(seed: number): () => number {
  let state = seed;
  return () => {
    state = (state + 0x6d2b79f5) >>> 0;
    let t = state;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

/**
 * The positions of `count` choices in the order to show them (Fisher–Yates with a generator
 * seeded by `seed`): `order[i]` is the file position of the choice shown i-th.
 */
export function choiceOrder(count: number, seed: string): number[] {
  const order = Array.from({ length: count }, (_, index) => index);
  const random = generator(hash(seed));
  for (let i = count - 1; i > 0; i--) {
    const j = Math.floor(random() * (i + 1));
    [order[i], order[j]] = [order[j], order[i]];
  }
  return order;
}
