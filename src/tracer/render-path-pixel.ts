import { Vector3 } from 'three';
import { PathIntegrator } from './path-integrator.ts';
import type { PathRecorder } from './path-recorder.ts';
import { Ray } from './ray.ts';
import { concentricDisc } from './lights.ts';
import { PIXEL_POSITION_STREAM, PIXEL_SCRAMBLE_STREAM } from './random-streams.ts';
import { hashIn, hashKey, RandomStream } from './sampler.ts';
import { pixelSamplePoint } from './sobol-pixel-samples.ts';
import type { TracerScene } from './tracer-scene.ts';

// One integrator per prepared scene, as for Whitted mode (render-pixel.ts).
const integrators = new WeakMap<TracerScene, PathIntegrator>();

export function pathIntegratorFor(scene: TracerScene): PathIntegrator {
  let integrator = integrators.get(scene);
  if (!integrator) {
    integrator = new PathIntegrator(scene);
    integrators.set(scene, integrator);
  }
  return integrator;
}

const direction = new Vector3();
const focalPoint = new Vector3();
const lensPoint = new Vector3();
const primary = new Ray();
const pathColor = new Vector3();
const random = new RandomStream();
const inPixel: [number, number] = [0, 0];

/**
 * The colour of pixel (x, y) in path mode (path-tracing spec §2): the mean of `paths` paths'
 * contributions, each started at a point of the pixel's square (a box filter): by default the
 * pixel's Owen-scrambled Sobol points (sobol-pixel-samples.ts), each uniform on its own but
 * spread evenly together, as Cycles and pbrt-v4 place pixel samples, or with `pixelSampling:
 * "independent"` independent uniform random points; through a uniform random point
 * of the lens when it has an aperture, at a uniform random moment of the open shutter when
 * the scene asks for more than one time sample. With
 * `recorder`, every path is recorded there, and the mean of their contributions, summed in
 * the same order, is this colour to the last bit.
 */
export function renderPathPixel(
  scene: TracerScene,
  x: number,
  y: number,
  width: number,
  height: number,
  seed: number,
  out: Vector3,
  recorder: PathRecorder | null,
  paths = scene.settings.pathSamples,
): Vector3 {
  out.set(0, 0, 0);
  return addPathSamples(scene, x, y, width, height, seed, 0, paths, out, recorder).divideScalar(paths);
}

/**
 * Adds the contributions of pixel (x, y)'s paths `from` … `to` − 1 to `sum`, one by one in
 * that order. The render window's progressive passes continue a pixel's sum pass after pass
 * (render-path-tile.ts): floating-point addition is not associative, so only a sum carried
 * on in the same order ends where one pass over all N paths ends, to the last bit.
 */
export function addPathSamples(
  scene: TracerScene,
  x: number,
  y: number,
  width: number,
  height: number,
  seed: number,
  from: number,
  to: number,
  sum: Vector3,
  recorder: PathRecorder | null = null,
): Vector3 {
  const integrator = pathIntegratorFor(scene);
  const { camera } = scene;
  const hasLens = camera.aperture > 0;
  const moving = scene.settings.timeSamples > 1;
  const stratified = scene.settings.pixelSampling === 'stratified';
  const scramble = hashKey(seed, x, y, 0, PIXEL_SCRAMBLE_STREAM);
  const scrambleU = hashIn(scramble, 0);
  const scrambleV = hashIn(scramble, 1);
  for (let sample = from; sample < to; sample++) {
    random.reset(hashKey(seed, x, y, sample, PIXEL_POSITION_STREAM));
    // An independent point takes the stream's first two numbers; the lens and shutter draw next.
    if (stratified) pixelSamplePoint(sample, scrambleU, scrambleV, inPixel);
    else {
      inPixel[0] = random.next();
      inPixel[1] = random.next();
    }
    camera.direction(x + inPixel[0], y + inPixel[1], width, height, direction);
    let time = 0;
    if (hasLens) {
      camera.focalPoint(direction, focalPoint);
      const [u, v] = concentricDisc(2 * random.next() - 1, 2 * random.next() - 1);
      camera.lensPoint(u, v, lensPoint);
      direction.subVectors(focalPoint, lensPoint).normalize();
    } else lensPoint.copy(camera.eye);
    if (moving) time = random.next();
    integrator.startSubSample(seed, x, y, sample, 0, time);
    primary.set(lensPoint, direction);
    primary.time = time;
    integrator.stats.primary++;
    sum.add(integrator.li(primary, pathColor, recorder));
  }
  return sum;
}
