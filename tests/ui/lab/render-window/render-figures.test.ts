import { describe, expect, it } from 'vitest';
import {
  countRays,
  formatCount,
  formatDuration,
  formatPercent,
  formatTimeLeft,
  formatWait,
  pathsOnShow,
  progressFraction,
  progressText,
  raysPerSecond,
} from '../../../../src/ui/lab/render-window/render-figures.ts';
import { formatShare } from '../../../../src/ui/lab/rt-ray-tooltip.ts';
import { inDutch } from '../../../support/page-locale.ts';

describe('render figures', () => {
  it('counts every kind of ray', () => {
    expect(countRays({ primary: 196_608, shadow: 300_000, reflect: 20_000, refract: 5_000 })).toBe(521_608);
  });

  it('divides rays by seconds, never by zero', () => {
    expect(raysPerSecond(3_000_000, 1500)).toBe(2_000_000);
    expect(raysPerSecond(1000, 0)).toBe(1_000_000);
  });

  it('writes an estimated wait in seconds, minutes, hours or days', () => {
    expect(formatWait(0.2)).toBe('1 s');
    expect(formatWait(75)).toBe('75 s');
    expect(formatWait(720)).toBe('12 min');
    expect(formatWait(3 * 3600)).toBe('3 h');
    expect(formatWait(27 * 86_400)).toBe('27 days');
  });

  it('writes counts in words with three significant digits', () => {
    expect(formatCount(950)).toBe('950');
    expect(formatCount(12_345)).toBe('12.3 thousand');
    expect(formatCount(4_561_000)).toBe('4.56 million');
    expect(formatCount(1_230_000)).toBe('1.23 million');
    expect(formatCount(2.1e9)).toBe('2.1 billion');
  });

  it('rounds before choosing the unit', () => {
    expect(formatCount(999_960)).toBe('1 million');
    expect(formatCount(999.7)).toBe('1 thousand');
  });

  it('writes durations in ms, seconds, or minutes and seconds', () => {
    expect(formatDuration(849.6)).toBe('850 ms');
    expect(formatDuration(1234)).toBe('1.23 s');
    expect(formatDuration(125_400)).toBe('2 min 5 s');
  });

  it('says the time left in steps that do not flicker: seconds under 20 s, then fives, then minutes', () => {
    expect(formatTimeLeft(7.4)).toBe('about 7 s left');
    expect(formatTimeLeft(47)).toBe('about 45 s left');
    expect(formatTimeLeft(48)).toBe('about 50 s left');
    expect(formatTimeLeft(151)).toBe('about 3 min left');
  });

  it('says which pass is under way and how far into it', () => {
    expect(progressText({ phase: 'preview', pass: 1, passes: 4, done: 3, total: 40 })).toBe('Step 1 of 4: quick preview 7.5 %');
    expect(progressText({ phase: 'sharp', pass: 3, passes: 4, done: 42, total: 100 })).toBe('Step 3 of 4: sharp picture (1 sample per pixel) 42 %');
    expect(progressText({ phase: 'final', pass: 4, passes: 4, done: 199, total: 200 })).toBe('Step 4 of 4: full quality 99 %');
    expect(progressText({ phase: 'final', pass: 1, passes: 1, done: 42, total: 100 })).toBe('Rendering 42 %');
  });

  it("counts path mode's paths per pixel, and fills the bar by the render's share of them", () => {
    const progress = { phase: 'final', pass: 40, passes: 259, done: 50, total: 100, paths: { done: 37, total: 256, fraction: 37.5 / 256 } } as const;
    expect(progressText(progress)).toBe('37 of 256 paths per pixel, 14 %');
    expect(progressFraction(progress)).toBe(37.5 / 256);
    expect(progressFraction({ ...progress, paths: null })).toBe(0.5);
    expect(pathsOnShow({ done: 37, total: 256, fraction: 0.2 })).toBe('Each of its pixels holds at least 37 of the 256 paths.');
  });

  it('shows a tenth of a percent under 10 %, rounded down, so a long pass moves and only a finished one reads 100 %', () => {
    expect(formatPercent(0, 16_777_216)).toBe('0.0 %');
    expect(formatPercent(16_777, 16_777_216)).toBe('0.0 %');
    expect(formatPercent(16_778, 16_777_216)).toBe('0.1 %');
    expect(formatPercent(57, 1000)).toBe('5.7 %');
    expect(formatPercent(99, 1000)).toBe('9.9 %');
    expect(formatPercent(100, 1000)).toBe('10 %');
    expect(formatPercent(999, 1000)).toBe('99 %');
    expect(formatPercent(1000, 1000)).toBe('100 %');
  });
});

describe('render figures in Dutch', () => {
  inDutch();

  it('write counts, times and shares with a decimal comma, in Dutch words', () => {
    expect(formatCount(12_345)).toBe('12,3 duizend');
    expect(formatCount(4_561_000)).toBe('4,56 miljoen');
    expect(formatDuration(1234)).toBe('1,23 s');
    expect(formatWait(40)).toBe('40 s');
    expect(formatShare(0.125)).toBe('12,5 %');
    // Not "&lt; 0,1 %": an escaped "<" in the catalogue came through as text.
    expect(formatShare(0.0004)).toBe('minder dan 0,1 %');
    // The render's progress under 10 % too (it read "2.5 %" in the Dutch window).
    expect(formatPercent(25, 1000)).toBe('2,5 %');
    expect(formatTimeLeft(150)).toBe('nog ongeveer 3 min');
    expect(progressText({ phase: 'final', pass: 3, passes: 9, done: 1, total: 2, paths: { done: 1024, total: 4096, fraction: 0.25 } })).toBe(
      '1.024 van de 4.096 paden per pixel, 25 %',
    );
  });
});
