/** A slider's `input` event: when (page time, ms) and the value it asked for. */
export interface SliderInput {
  at: number;
  value: number;
}

/** A frame that showed rays of a new value: when, and that value. */
export type SliderFrame = SliderInput;

export interface SliderLatencyFigures {
  /** Steps: inputs that asked for a new value. */
  steps: number;
  p50Ms: number;
  p95Ms: number;
  maxMs: number;
  /** Whether the last frame shows the last value asked for. */
  lastDrawn: boolean;
  /** Steps no frame ever showed (neither their value nor a later one). */
  undrawn: number;
  /** Frames that showed new rays before the last step: rays kept coming while the slider moved. */
  shownDuring: number;
}

/**
 * Each step's time from its input to the first frame after it that shows its value or one
 * beyond it, for a slider moved one way (up): a later value's rays also show the step done,
 * which is how "latest wins" may skip a value in between but never the last one.
 */
export function sliderLatencyOf({ inputs, frames }: { inputs: SliderInput[]; frames: SliderFrame[] }): SliderLatencyFigures {
  const steps = inputs.filter((input, index) => index === 0 || input.value !== inputs[index - 1].value);
  const latencies: number[] = [];
  let undrawn = 0;
  for (const step of steps) {
    const shown = frames.find((frame) => frame.at >= step.at && frame.value >= step.value);
    if (shown) latencies.push(shown.at - step.at);
    else undrawn++;
  }
  const sorted = [...latencies].sort((a, b) => a - b);
  const percentile = (p: number) => (sorted.length === 0 ? NaN : sorted[Math.min(sorted.length - 1, Math.ceil(p * sorted.length) - 1)]);
  const round = (ms: number) => Math.round(ms * 10) / 10;
  return {
    steps: steps.length,
    p50Ms: round(percentile(0.5)),
    p95Ms: round(percentile(0.95)),
    maxMs: round(sorted.at(-1) ?? NaN),
    lastDrawn: steps.length > 0 && frames.at(-1)?.value === steps.at(-1)!.value,
    undrawn,
    shownDuring: steps.length > 0 ? frames.filter((frame) => frame.at < steps.at(-1)!.at).length : 0,
  };
}
