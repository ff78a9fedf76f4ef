import { describe, expect, it } from 'vitest';
import { learnerKey, MAX_NUMBERED_CODES, normalParticipantCode, numberedCodes } from '../../src/classroom/participant-code.ts';
import { PARTICIPANT_CODE } from '../../src/classroom/learner-identity.ts';

describe('participant codes as one learner', () => {
  it('matches a code whatever its case or surrounding spaces', () => {
    expect(normalParticipantCode('5h2-03')).toBe('5H2-03');
    expect(normalParticipantCode(' 5H2-03 ')).toBe('5H2-03');
    expect(normalParticipantCode('5h2-03')).toBe(normalParticipantCode('5H2-03'));
    // A letter typed as base + accent is the same as the composed one.
    expect(normalParticipantCode('e\u0301')).toBe(normalParticipantCode('\u00e9'));
  });

  it('compares a learner id that is the participant code in the normal form, and keeps other ids as they are', () => {
    expect(learnerKey('p-07', 'p-07')).toBe('P-07');
    expect(learnerKey('p-07', 'P-07 ')).toBe('P-07');
    const install = 'install:0f8fad5b-d9cb-469f-a165-70867728950e';
    expect(learnerKey(install, '')).toBe(install);
    expect(learnerKey('file:a.csv', '')).toBe('file:a.csv');
    expect(learnerKey('learner-1', 'P-4')).toBe('learner-1');
  });

  it('numbers a class list of codes from 01, each a valid code', () => {
    const codes = numberedCodes('5h2', 30);
    expect(codes).toHaveLength(30);
    expect(codes[0]).toBe('5H2-01');
    expect(codes[2]).toBe('5H2-03');
    expect(codes[29]).toBe('5H2-30');
    expect(new Set(codes).size).toBe(30);
    for (const code of codes) expect(PARTICIPANT_CODE.test(code)).toBe(true);
  });

  it('pads to the digits of the largest number, and bounds the count', () => {
    expect(numberedCodes('A', 120)[0]).toBe('A-001');
    expect(numberedCodes('', 2)).toEqual(['P-01', 'P-02']);
    expect(numberedCodes('5 H2!', 1)).toEqual(['5H2-01']);
    expect(numberedCodes('A', -3)).toEqual([]);
    expect(numberedCodes('A', 10_000)).toHaveLength(MAX_NUMBERED_CODES);
  });
});
