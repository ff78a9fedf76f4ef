/**
 * The "Negligible below" slider, as a share of the pixel: it spans 0–20 %, where the
 * interesting thresholds are (a bounce typically carries a few percent), in 0.5 % steps, so
 * that a drag lands on a round value such as 10 % (issue 37: in 0.1 % steps the slider's
 * 200 stops were a pixel or two wide each, and 10 % took four drags). Finer shares, and any
 * share up to 100 %, can be typed.
 */
export const NEGLIGIBLE_THRESHOLD = { min: 0, max: 0.2, step: 0.005, inputMax: 1 } as const;
