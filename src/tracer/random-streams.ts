import { LIMITS } from '../scene/scene-limits.ts';

/**
 * The tracer's random streams, each a name for the number that keeps its random numbers
 * apart from every other's (sampler.ts: a stream is a key hashed from integers, so two uses
 * that hash the same integers draw the same numbers, and a lens point would be correlated
 * with, say, an area light's sample).
 *
 * A stream's number takes the place of an index in the key, so it must be no index that can
 * stand there:
 * - a pixel sample's streams, hashKey(seed, x, y, sample, stream), share that place with a
 *   lens/time ray's sub-sample index (WhittedIntegrator.startSubSample), 0 … n²·k − 1;
 * - a hit's streams, hashKey(sampleKey, stream, evaluation), share it with an area light's
 *   index (its jittered samples), 0 … lights − 1.
 * tests/tracer/random-streams.test.ts checks that the streams are distinct and above both
 * bounds, which come from the scene's limits. The numbers themselves are arbitrary, and
 * fixed: changing one changes every image that draws from it (the golden images).
 */

/**
 * Sub-pixel positions of the jittered and random sample patterns (supersampling.ts); in path
 * mode, a path's lens point and shutter time (render-path-pixel.ts).
 */
export const PIXEL_POSITION_STREAM = 0x5a17;
/**
 * Path mode: a pixel's Owen-scrambling seeds for its stratified points (render-path-pixel.ts),
 * keyed as its first sample's stream, as the scrambling is the same for all its samples.
 */
export const PIXEL_SCRAMBLE_STREAM = 0x5c4a;
/** A pixel sample's jittered lens points (render-pixel.ts). */
export const LENS_STREAM = 0x1e25;
/** A pixel sample's shutter times (shutter-times.ts). */
export const SHUTTER_TIME_STREAM = 0x71fe;
/** A hit's glossy directions (whitted-integrator.ts). */
export const GLOSS_STREAM = 0x6c055;
/** A path's random numbers at each bounce, keyed by the bounce (path-integrator.ts). */
export const PATH_BOUNCE_STREAM = 0x3b0c;

/** Where in a key a stream's number stands, and so which indices it must stay clear of. */
export type StreamPlace = 'pixel sample' | 'hit';

/** Every stream, with its place in the key. */
export const RANDOM_STREAMS: readonly { name: string; stream: number; place: StreamPlace }[] = [
  { name: 'pixel position', stream: PIXEL_POSITION_STREAM, place: 'pixel sample' },
  { name: 'pixel scramble', stream: PIXEL_SCRAMBLE_STREAM, place: 'pixel sample' },
  { name: 'lens', stream: LENS_STREAM, place: 'pixel sample' },
  { name: 'shutter time', stream: SHUTTER_TIME_STREAM, place: 'pixel sample' },
  { name: 'gloss', stream: GLOSS_STREAM, place: 'hit' },
  { name: 'path bounce', stream: PATH_BOUNCE_STREAM, place: 'hit' },
];

/**
 * The most lens/time rays one pixel sample casts, n²·k: the sub-sample indices run below it.
 * Also bounded by the primary rays of a whole pixel, s²·n²·k.
 */
export const MAX_SUB_SAMPLES = Math.min(LIMITS.lensSamples[1] ** 2 * LIMITS.timeSamples[1], LIMITS.primaryRaysPerPixel[1]);

/** The most lights a scene has: the light indices run below it. */
export const MAX_LIGHTS = LIMITS.lightCount[1];
