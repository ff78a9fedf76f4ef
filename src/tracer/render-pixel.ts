import { Vector3 } from 'three';
import type { RayNode } from './ray-tree.ts';
import { Ray } from './ray.ts';
import { samplePosition } from './supersampling.ts';
import type { TracerScene } from './tracer-scene.ts';
import { WhittedIntegrator } from './whitted-integrator.ts';

// One integrator per prepared scene: its scratch frames are sized by the scene's maxDepth.
const integrators = new WeakMap<TracerScene, WhittedIntegrator>();

export function integratorFor(scene: TracerScene): WhittedIntegrator {
  let integrator = integrators.get(scene);
  if (!integrator) {
    integrator = new WhittedIntegrator(scene);
    integrators.set(scene, integrator);
  }
  return integrator;
}

const position: [number, number] = [0, 0];
const direction = new Vector3();
const primary = new Ray();
const sampleColor = new Vector3();

/**
 * The colour of pixel (x, y) of a width×height image: the mean of its s×s supersamples,
 * each weighted 1/s² (spec §2). With `roots`, each sample's ray tree is recorded there.
 * The image and the ray tree both come from here, so they always agree.
 * @param s samples per side; the scene's supersampling unless a preview asks for 1
 */
export function renderPixel(
  scene: TracerScene, x: number, y: number, width: number, height: number, seed: number,
  out: Vector3, roots: RayNode[] | null, s = scene.settings.supersampling,
): Vector3 {
  const integrator = integratorFor(scene);
  const samplePattern = scene.settings.samplePattern;
  const samples = s * s;
  out.set(0, 0, 0);
  for (let k = 0; k < samples; k++) {
    samplePosition(samplePattern, s, k, x, y, seed, position);
    scene.camera.direction(x + position[0], y + position[1], width, height, direction);
    primary.set(scene.camera.eye, direction);
    integrator.startPixelSample(seed, x, y, k);
    integrator.stats.primary++;
    let root: RayNode | null = null;
    if (roots) {
      root = primaryNode(primary);
      roots.push(root);
    }
    out.add(integrator.trace(primary, 0, sampleColor, root));
  }
  return out.divideScalar(samples);
}

function primaryNode(ray: Ray): RayNode {
  return {
    type: 'primary', origin: ray.origin.toArray(), direction: ray.direction.toArray(), length: 0, hit: false,
    objectId: null, lightId: null, color: [0, 0, 0], contribution: 0, children: [],
  };
}
