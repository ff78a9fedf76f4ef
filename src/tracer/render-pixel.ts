import { Vector3 } from 'three';
import { LIMITS } from '../scene/scene-limits.ts';
import { discPointBuffer, jitteredDiscPoints } from './disc-samples.ts';
import type { PixelRecording, RayObserver } from './ray-recorder.ts';
import { Ray } from './ray.ts';
import { LENS_STREAM } from './random-streams.ts';
import { hashKey, RandomStream } from './sampler.ts';
import { shutterTimes } from './shutter-times.ts';
import { samplePosition } from './supersampling.ts';
import type { TracerScene } from './tracer-scene.ts';
import { WhittedIntegrator } from './whitted-integrator.ts';
import { pathIntegratorFor, renderPathPixel } from './render-path-pixel.ts';
import type { Estimator } from './estimator.ts';

// One integrator per prepared scene: its scratch frames are sized by the scene's maxDepth.
const integrators = new WeakMap<TracerScene, WhittedIntegrator>();

/** The scene's estimator, as the tile loop sees it: its ray counts and the tile's primary candidates. */
export function integratorFor(scene: TracerScene): Estimator<unknown> {
  return scene.settings.integrator === 'path' ? pathIntegratorFor(scene) : whittedIntegratorFor(scene);
}

function whittedIntegratorFor(scene: TracerScene): WhittedIntegrator {
  let integrator = integrators.get(scene);
  if (!integrator) {
    integrator = new WhittedIntegrator(scene);
    integrators.set(scene, integrator);
  }
  return integrator;
}

const position: [number, number] = [0, 0];
const direction = new Vector3();
const focalPoint = new Vector3();
const lensPoint = new Vector3();
const lensDirection = new Vector3();
const primary = new Ray();
const sampleColor = new Vector3();
const subSampleColor = new Vector3();
const random = new RandomStream();
const lensPoints = discPointBuffer();
const times = new Float64Array(LIMITS.timeSamples[1]);

/**
 * The colour of pixel (x, y) of a width×height image: the mean of its s×s supersamples,
 * each weighted 1/s² (spec §2). With `tree`, each sample's ray tree is told to it (a
 * RayTreeRecording records them all).
 * The image and the ray tree both come from here, so they always agree.
 *
 * A sample with a lens (aperture > 0, n×n lens points) or a shutter (k > 1 times) casts
 * n²·k primary rays, each weighted 1/(n²·k) (distribution-effects §2). With more than one,
 * its root is the pinhole ray to the plane in focus (hit, length to F, no object), with one
 * child per lens point and time (§3); with one, that ray is the root.
 *
 * In path mode the pixel is the mean of its paths (render-path-pixel.ts); its ray tree is
 * not recorded here (a pixel's paths are: tracePaths).
 * @param s samples per side; the scene's supersampling (path mode: its pathSamples) unless a preview asks for 1 (path mode: s² paths)
 * @param onlySample one of Whitted mode's s × s samples traced alone: the colour is that sample's, the tree has only its rays (trace-within-budget.ts)
 */
export function renderPixel(
  scene: TracerScene,
  x: number,
  y: number,
  width: number,
  height: number,
  seed: number,
  out: Vector3,
  tree: PixelRecording | null,
  samplesPerPixel?: number,
  onlySample?: number,
): Vector3 {
  if (scene.settings.integrator === 'path') return renderPathPixel(scene, x, y, width, height, seed, out, null, samplesPerPixel);
  // Whitted mode's samples are a square s × s.
  const s = samplesPerPixel === undefined ? scene.settings.supersampling : Math.round(Math.sqrt(samplesPerPixel));
  const integrator = whittedIntegratorFor(scene);
  const { camera } = scene;
  const samplePattern = scene.settings.samplePattern;
  const samples = s * s;
  const n = camera.lensSamplesPerSide;
  const k = scene.settings.timeSamples;
  const timePattern = scene.settings.timePattern;
  const lensRays = n * n;
  const hasLens = camera.aperture > 0;
  // One ray per sample through the pinhole at time 0 is today's tracer, to the bit.
  const distributed = hasLens || k > 1;
  // More than one ray per sample: the root is the pinhole ray, the rays are its children.
  const nested = lensRays * k > 1;
  const weight = 1 / (lensRays * k);
  const firstSample = onlySample ?? 0;
  const endSample = onlySample === undefined ? samples : onlySample + 1;
  out.set(0, 0, 0);
  for (let sample = firstSample; sample < endSample; sample++) {
    samplePosition(samplePattern, s, sample, x, y, seed, position);
    camera.direction(x + position[0], y + position[1], width, height, direction);
    integrator.startPixelSample(seed, x, y, sample);
    if (!distributed) {
      primary.set(camera.eye, direction);
      primary.time = 0;
      if (tree?.skips() === true) continue;
      integrator.stats.primary++;
      out.add(integrator.li(primary, sampleColor, tree ? tree.sampleRay(primary) : null));
      continue;
    }
    // The pinhole ray meets the plane in focus at F; every lens ray aims at F.
    camera.focalPoint(direction, focalPoint);
    if (hasLens) jitteredDiscPoints(n, random.reset(hashKey(seed, x, y, sample, LENS_STREAM)), lensPoints);
    // k times in the open shutter, by the time pattern; every lens point is traced at each of them.
    shutterTimes(timePattern, k, seed, x, y, sample, times);
    if (tree && nested) tree.pinholeRay(primary.set(camera.eye, direction), focalPoint.distanceTo(camera.eye));
    sampleColor.set(0, 0, 0);
    for (let lens = 0; lens < lensRays; lens++) {
      if (hasLens) {
        camera.lensPoint(lensPoints[lens * 2], lensPoints[lens * 2 + 1], lensPoint);
        lensDirection.subVectors(focalPoint, lensPoint).normalize();
      } else {
        lensPoint.copy(camera.eye);
        lensDirection.copy(direction);
      }
      for (let i = 0; i < k; i++) {
        if (tree?.skips() === true) continue;
        integrator.startSubSample(seed, x, y, sample, lens * k + i, times[i]);
        primary.set(lensPoint, lensDirection);
        primary.time = times[i];
        integrator.stats.primary++;
        const ray: RayObserver | null = tree ? tree.lensRay(primary, lensPoint, times[i], weight) : null;
        sampleColor.addScaledVector(integrator.li(primary, subSampleColor, ray), weight);
      }
    }
    tree?.sampleDone(sampleColor);
    out.add(sampleColor);
  }
  return out.divideScalar(endSample - firstSample);
}
