import type { Color } from '../../scene/scene.ts';

/**
 * Scene colours as the hex codes of <input type="color"> (pure: tested in Node).
 *
 * No gamma: the scene's colours are linear [r, g, b] in 0..1, and the tracer writes its
 * image without a transfer curve (as the Virtual Ray Tracer does), so a channel c is shown
 * on screen as round(c · 255). Showing the picker the same number keeps "what you pick is
 * what the render shows"; an sRGB conversion here would make every picked colour render
 * darker than the swatch.
 */

/** "#e6261a" for [0.9, 0.15, 0.1]. */
export function colorToHex(color: Color): string {
  return (
    '#' +
    color
      .map((c) =>
        Math.round(Math.min(1, Math.max(0, c)) * 255)
          .toString(16)
          .padStart(2, '0'),
      )
      .join('')
  );
}

/** [r, g, b] in 0..1 from "#rrggbb", "rrggbb", "#rgb" or "rgb" (any case); undefined otherwise. */
export function hexToColor(text: string): Color | undefined {
  const match = /^#?([0-9a-f]{3}|[0-9a-f]{6})$/i.exec(text.trim());
  if (!match) return undefined;
  const digits = match[1].length === 3 ? [...match[1]].map((d) => d + d).join('') : match[1];
  return [0, 2, 4].map((i) => parseInt(digits.slice(i, i + 2), 16) / 255) as Color;
}
