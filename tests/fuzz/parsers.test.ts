import { describe, expect, it } from 'vitest';
import { fuzz, fuzzTargets } from './fuzz-targets.ts';

// Every parser of outside input against 1,000 generated cases (`npm run fuzz` runs 10,000
// and prints the table): no throw, no malformed result, none slower than HANG_MS, and the
// cases reach both sides, acceptance and refusal.

const CASES = 1000;
const targets = await fuzzTargets();

describe('fuzzed parsers', () => {
  it.each(targets.map((target) => [target.name, target] as const))(
    '%s: every case is accepted or refused with reasons, none crashes or hangs',
    async (_, target) => {
      const tally = await fuzz(target, CASES);
      expect(tally.firstProblem).toBeNull();
      expect({ crashed: tally.crashed, hangs: tally.hangs, cases: tally.cases }).toEqual({ crashed: 0, hangs: 0, cases: CASES });
      expect(tally.accepted).toBeGreaterThan(0);
      expect(tally.refused).toBeGreaterThan(0);
    },
  );
});
