/**
 * The ray tracer's work for one pixel as 16 lines of pseudocode (ray-debugger spec §2), by
 * stable ids. The words are the UI's (they are translated); the order is the lines' order.
 * Each debugger step lights one line (debug-steps.ts says which).
 */
export const PSEUDOCODE_LINES = [
  /** for each sample of the pixel: */
  'sample-loop',
  /** for each lens point and each moment (a lens or an open shutter casts several): */
  'lens-loop',
  /** colour ← trace(primary ray, depth 0) */
  'trace-primary',
  /** pixel ← Σ share × colour */
  'average',
  /** trace(ray, depth): */
  'trace',
  /** find the nearest hit; nothing hit: return the background */
  'nearest-hit',
  /** colour ← ka·C + Σ la·Lc·C */
  'ambient',
  /** for each light (an area light: each of its samples, with I ÷ their number): */
  'light-loop',
  /** if N·L > 0, A > 0 and Shadows is on: cast a shadow ray toward the light */
  'shadow-ray',
  /** blocked: S = 0, it adds nothing */
  'blocked',
  /** reaches it: colour += I·A·(max(N·L,0)·kd·ld·Lc·C + max(R·V,0)ⁿ·ks·ls·Lc) */
  'lit',
  /** opaque with ks > 0, below the maximum depth: colour += ks·trace(reflected ray, depth + 1) */
  'mirror',
  /** glass, below the maximum depth: kr ← Schlick, kt ← 1 − kr */
  'schlick',
  /** colour += kt·trace(refracted ray) + kr·trace(reflected ray) */
  'glass',
  /** rough: m×m rays around each ideal one, each with 1/m² of its weight */
  'glossy',
  /** return clamp(colour, 0, 1) */
  'return',
] as const;

export type PseudocodeLine = (typeof PSEUDOCODE_LINES)[number];

/** How far each line is indented (for drawing it as code). */
export const LINE_INDENT: Record<PseudocodeLine, number> = {
  'sample-loop': 0,
  'lens-loop': 1,
  'trace-primary': 2,
  average: 0,
  trace: 0,
  'nearest-hit': 1,
  ambient: 1,
  'light-loop': 1,
  'shadow-ray': 2,
  blocked: 2,
  lit: 2,
  mirror: 1,
  schlick: 1,
  glass: 2,
  glossy: 2,
  return: 1,
};
