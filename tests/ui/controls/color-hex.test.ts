import { expect, test } from 'vitest';
import { colorToHex, hexToColor } from '../../../src/ui/controls/color-hex.ts';

test('a linear colour shows as round(c · 255), with no gamma curve', () => {
  expect(colorToHex([0.9, 0.15, 0.1])).toBe('#e6261a');
  expect(colorToHex([0.5, 0.5, 0.5])).toBe('#808080'); // sRGB encoding would give #bcbcbc
  expect(colorToHex([0, 1, 1])).toBe('#00ffff');
});

test('channels outside 0..1 are clamped rather than written as three-digit hex', () => {
  expect(colorToHex([-0.2, 1.5, 0.5])).toBe('#00ff80');
});

test('reads #rrggbb and #rgb, with or without #, in any case', () => {
  expect(hexToColor('#ff8000')).toEqual([1, 128 / 255, 0]);
  expect(hexToColor('FF8000')).toEqual([1, 128 / 255, 0]);
  expect(hexToColor(' #f80 ')).toEqual([1, 136 / 255, 0]);
});

test('refuses anything else', () => {
  for (const text of ['', '#', '#ff80', '#gg0000', 'red', '#ff80000', 'rgb(1,0,0)']) expect(hexToColor(text), text).toBeUndefined();
});

test('hex → colour → hex gives the same code', () => {
  for (const hex of ['#000000', '#ffffff', '#e6261a', '#123abc']) expect(colorToHex(hexToColor(hex)!)).toBe(hex);
});
