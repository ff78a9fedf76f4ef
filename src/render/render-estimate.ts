/**
 * How much a render will cost before it starts: rays and seconds from the scene and the
 * image size. The render window shows it and asks before a heavy render, `rt render`
 * refuses one without --force, and the render pool scales its per-tile deadlines by it.
 *
 * The model follows the Whitted ray tree (whitted-integrator.ts). Every sample starts a
 * primary ray; every hit casts one shadow ray per point or spot light and n² per n×n area
 * light; a mirror (opaque, specular > 0) spawns a reflected ray and glass (transparent) a
 * reflected and a refracted one, down to settings.maxDepth. With b child rays per hit on
 * average over the objects and a chance p that a child ray hits anything, the tree has
 * Σ_{d=0..D} (p·b)^d hits per sample. A pixel casts s²·n²·k primary rays (supersampling,
 * lens points, shutter times) and a rough material m² rays where a smooth one casts one. p = ½ is a guess that puts the schema's heaviest scene
 * (256 glass objects, depth 10, 32 area lights of 10×10, 8×8 samples, 4096²) at 27 days on
 * 8 workers, near the 38 days measured, not centuries (p = 1 would say 55 years); the
 * default scene and the levels' scenes come out at 0.7 to 3 times the rays they really
 * trace. It is an estimate for deciding, not a promise: it sizes tiles and previews and says
 * whether a render may be long. How long one really takes on this machine is measured
 * (measured-estimate.ts, render-probe.ts).
 */
import type { Scene } from '../scene/scene.ts';

/**
 * Rays one worker traces per second, on the slow side of the machines that run the game
 * (the benchmark measured 4.8 million per worker thread, mostly cheap shadow rays, on the
 * reference machine): a school laptop should not finish much later than promised.
 */
export const RAYS_PER_SECOND_PER_WORKER = 2_000_000;

/** Above this the learner is asked first (the render window) and `rt render` wants --force. */
export const HEAVY_RENDER_SECONDS = 60;

/** The chance that a reflected or refracted ray hits an object (see the model above). */
const CHILD_HIT_CHANCE = 0.5;

export interface RenderEstimate {
  /** Rays of the full-quality image: primary, shadow, reflected and refracted. */
  rays: number;
  raysPerPixel: number;
  /** On `workers` workers at RAYS_PER_SECOND_PER_WORKER each. */
  seconds: number;
  /** seconds > HEAVY_RENDER_SECONDS. */
  heavy: boolean;
}

/** Shadow rays per hit: one per point or spot light, n² per n×n area light (counted even with
 *  shadows off: the light is still sampled n² times). */
export function shadowRaysPerHit({ lights, settings }: Scene): number {
  return lights.filter((light) => settings.lightTypes[light.type]).reduce((rays, light) => rays + (light.type === 'area' ? light.samples ** 2 : 1), 0);
}

/** Rays one sample (one primary ray and its tree) costs. */
export function raysPerSample(scene: Scene): number {
  const { objects, settings } = scene;
  const shadowRays = shadowRaysPerHit(scene);
  // A path: at most maxDepth + 1 vertices, each with one light sample per light. An upper
  // bound: paths that escape or end by roulette cost less.
  if (settings.integrator === 'path') return (settings.maxDepth + 1) * (1 + scene.lights.filter((light) => settings.lightTypes[light.type]).length);
  // A rough material spreads each of its reflected and refracted rays into m² (distribution-effects §2).
  const childRays = objects.reduce((sum, { material }) => {
    const spread = material.roughness > 0 ? material.glossySamples ** 2 : 1;
    return sum + spread * (material.transparent ? 2 : material.specular > 0 ? 1 : 0);
  }, 0);
  const branching = objects.length === 0 ? 0 : (CHILD_HIT_CHANCE * childRays) / objects.length;
  let hits = 0;
  for (let depth = 0, level = 1; depth <= settings.maxDepth; depth++, level *= branching) hits += level;
  // Every hit casts its shadow rays; each hit's own ray is counted once (the primary or a child).
  return hits * (1 + shadowRays);
}

/**
 * Primary rays of one pixel sample: n² lens points (with an aperture) at k shutter times
 * (distribution-effects §2); 1 for a pinhole and a closed-at-once shutter.
 */
export function primaryRaysPerSample({ camera, settings }: Scene): number {
  // Path mode: every path has one primary ray, its lens point and moment its own.
  if (settings.integrator === 'path') return 1;
  return (camera.aperture > 0 ? camera.lensSamples ** 2 : 1) * settings.timeSamples;
}

/** Samples per pixel: s² (supersampling), or path mode's N paths. */
export function samplesPerPixel({ settings }: Scene): number {
  return settings.integrator === 'path' ? settings.pathSamples : settings.supersampling ** 2;
}

/** Primary rays per pixel: samplesPerPixel samples of primaryRaysPerSample each. */
export function primaryRaysPerPixel(scene: Scene): number {
  return samplesPerPixel(scene) * primaryRaysPerSample(scene);
}

/**
 * Rays and seconds of a `width × height` render of a scene: the model's (`modelEstimate`) or
 * one priced by a probe of the scene on this machine (measured-estimate.ts).
 */
export type EstimateRender = (scene: Scene, width: number, height: number) => RenderEstimate;

/** The model's estimates on `workers` workers, as an EstimateRender. */
export function modelEstimate(workers: number): EstimateRender {
  return (scene, width, height) => estimateRender(scene, width, height, workers);
}

/** Rays and seconds of a `width × height` render of `scene` on `workers` workers. */
export function estimateRender(scene: Scene, width: number, height: number, workers = 1): RenderEstimate {
  const raysPerPixel = raysPerSample(scene) * primaryRaysPerPixel(scene);
  const rays = raysPerPixel * width * height;
  const seconds = rays / (RAYS_PER_SECOND_PER_WORKER * Math.max(1, workers));
  return { rays, raysPerPixel, seconds, heavy: seconds > HEAVY_RENDER_SECONDS };
}

/** A change that makes a heavy render lighter, with its estimate: for the learner to pick. */
export type LighterRender =
  | { change: 'supersampling'; supersampling: number; estimate: RenderEstimate }
  | { change: 'path-samples'; pathSamples: number; estimate: RenderEstimate }
  | { change: 'image-size'; width: number; height: number; estimate: RenderEstimate }
  | { change: 'max-depth'; maxDepth: number; estimate: RenderEstimate };

/**
 * For a heavy render, the mildest change of each kind that brings it under
 * HEAVY_RENDER_SECONDS by `estimateRender`: fewer samples, a smaller image (same aspect
 * ratio), a shallower ray tree. A kind that cannot get there alone is left out; none for a
 * render that is not heavy. In path mode fewer samples are fewer paths per pixel (supersampling
 * has no meaning there): the largest power of two below N that is light enough, the counts
 * the Monte Carlo level compares (1, 4, 16, 64, 256), each halving of N making the noise
 * √2 times larger.
 */
export function lighterRenders(scene: Scene, width: number, height: number, estimate: EstimateRender): LighterRender[] {
  const full = estimate(scene, width, height);
  if (!full.heavy) return [];
  const lighter: LighterRender[] = [];
  const withSettings = (changes: Partial<Scene['settings']>): Scene => ({ ...scene, settings: { ...scene.settings, ...changes } });
  if (scene.settings.integrator === 'path') {
    for (let pathSamples = 2 ** Math.floor(Math.log2(scene.settings.pathSamples - 1)); pathSamples >= 1; pathSamples /= 2) {
      const fewer = estimate(withSettings({ pathSamples }), width, height);
      if (!fewer.heavy) {
        lighter.push({ change: 'path-samples', pathSamples, estimate: fewer });
        break;
      }
    }
  }
  for (let supersampling = scene.settings.integrator === 'path' ? 0 : scene.settings.supersampling - 1; supersampling >= 1; supersampling--) {
    const smaller = estimate(withSettings({ supersampling }), width, height);
    if (!smaller.heavy) {
      lighter.push({ change: 'supersampling', supersampling, estimate: smaller });
      break;
    }
  }
  // Time grows with the pixel count: scale both sides by the square root of the overshoot.
  const factor = Math.sqrt(HEAVY_RENDER_SECONDS / full.seconds);
  const [smallWidth, smallHeight] = [Math.floor(width * factor), Math.floor(height * factor)];
  if (smallWidth >= 1 && smallHeight >= 1) {
    lighter.push({ change: 'image-size', width: smallWidth, height: smallHeight, estimate: estimate(scene, smallWidth, smallHeight) });
  }
  for (let maxDepth = scene.settings.maxDepth - 1; maxDepth >= 0; maxDepth--) {
    const shallower = estimate(withSettings({ maxDepth }), width, height);
    if (!shallower.heavy) {
      lighter.push({ change: 'max-depth', maxDepth, estimate: shallower });
      break;
    }
  }
  return lighter;
}
