/**
 * Russian roulette's chance that a path goes on, from the largest channel β of its
 * throughput: min(1, √β), Cycles' rule (path_state_continuation_probability in
 * kernel/integrator/path_state.h). Any chance above 0 keeps the estimate unbiased, since a
 * survivor's throughput is divided by it (Arvo and Kirk 1990; pbrt-v4 §2.2.4). pbrt-v4's
 * path tracer (§13.4) goes on with chance β itself, so a survivor weighs 1/β times more: with
 * uniform bounces and no light sampling, the rare paths that reach the light then weigh so
 * much that 64 paths per pixel seldom see one (docs/path-tracing.md, "Checked against
 * Cycles"). The square root stops fewer dim paths, and a survivor weighs only 1/√β times more.
 */
export function rouletteSurvival(largestThroughput: number): number {
  return Math.min(1, Math.sqrt(largestThroughput));
}
