/**
 * Honest estimates (issue 37: "313 × 313 (about 60 s)" took 2 min 31 s): heavy renders of
 * the levels' distribution-effects scenes, estimated as the render window estimates them
 * (render-probe.ts: a probe of the scene on this machine) and then rendered as the window
 * renders them (previews first, two workers), after a small render of the scene (a learner's
 * workers have traced the level before its settings are made heavy; a fresh pool's first
 * probe rounds ran unoptimized code and priced the first case at twice its real time, 0.48
 * and 0.59 in two runs), at the image size (of the case's aspect) that
 * the estimate puts at ASKED_SECONDS, whatever this machine's speed. For each, the window's
 * question names a smaller image "(about 60 s)"; that render is made and timed, and its real time over its
 * estimate must lie in [1/1.5, 1.5]. The cases run in one session, as a learner's renders
 * do, so each later estimate is corrected by how the earlier ones came true
 * (estimate-calibration.ts). The model's estimate of the same render (render-estimate.ts),
 * which the window used before, is given beside it.
 */
import { issueLine } from '../src/util/issue.ts';
import { readScene } from '../src/cli/scene-file.ts';
import { createNodeRenderPool } from '../src/cli/node-worker-port.ts';
import { EstimateCalibration } from '../src/render/estimate-calibration.ts';
import { estimateRender, lighterRenders } from '../src/render/render-estimate.ts';
import { estimateHere } from '../src/render/render-probe.ts';
import { loadMeshesFromDisk } from '../src/scene/load-meshes-node.ts';
import { meshNamesInScene } from '../src/scene/mesh-names.ts';
import { parseScene } from '../src/scene/scene-schema.ts';
import type { Scene } from '../src/scene/scene.ts';

/** The range a render's real time over its estimate must lie in. */
export const ESTIMATE_RATIO_LIMIT = 1.5;

/** The heavy render asked for: about the 2 min 31 s of issue 37's. */
const ASKED_SECONDS = 150;

export interface EstimateCase {
  name: string;
  /** The heavy render asked for, and the window's estimate of it (s). */
  asked: { width: number; height: number; seconds: number };
  /** The smaller image the window suggested, its estimate, the model's, and the real render (s). */
  suggested: { width: number; height: number; seconds: number; modelSeconds: number; realSeconds: number };
  /** Real over estimated: within [1/1.5, 1.5]. */
  ratio: number;
  /** The session's correction the estimate was made with. */
  correction: number;
}

/** A level's scene with `edit` applied to its scene file, checked by the schema. */
async function levelScene(level: string, edit: (scene: Record<string, unknown>) => Record<string, unknown>): Promise<Scene> {
  const { scene } = await readScene(level);
  const parsed = parseScene(edit(structuredClone(scene) as unknown as Record<string, unknown>));
  if (!parsed.ok) throw new Error(`the ${level} bench scene is invalid:\n${parsed.errors.map(issueLine).join('\n')}`);
  return parsed.scene;
}

/** The heavy settings: lens and area-light samples, supersampling, glossy samples; each size gives its aspect ratio (the render is scaled to ASKED_SECONDS). */
async function cases(): Promise<{ name: string; scene: Scene; width: number; height: number }[]> {
  const depthOfField = await levelScene('18-depth-of-field', (scene) => ({
    ...scene,
    camera: { ...(scene.camera as object), aperture: 0.3, focusDistance: 11, lensSamples: 6 },
    lights: [{ id: 'panel', type: 'area', position: [-4, 4, 2], size: [1, 1], samples: 4, intensity: 0.9 }],
  }));
  const supersampled = await levelScene('12-seeing-many-rays', (scene) => ({ ...scene, settings: { ...(scene.settings as object), supersampling: 6 } }));
  const glossy = await levelScene('19-glossy-reflections', (scene) => ({
    ...scene,
    settings: { ...(scene.settings as object), supersampling: 3 },
    objects: (scene.objects as { material: object }[]).map((object) => ({ ...object, material: { ...object.material, roughness: 0.2, glossySamples: 5 } })),
  }));
  return [
    { name: 'level 18, lens 6×6, area light 4×4', scene: depthOfField, width: 1024, height: 1024 },
    { name: 'level 12, supersampling 6×6', scene: supersampled, width: 1280, height: 960 },
    { name: 'level 19, glossy 5×5, supersampling 3×3', scene: glossy, width: 1200, height: 800 },
  ];
}

export async function measureEstimates(): Promise<EstimateCase[]> {
  const pool = createNodeRenderPool(2);
  const calibration = new EstimateCalibration();
  const results: EstimateCase[] = [];
  try {
    for (const { name, scene, width, height } of await cases()) {
      const meshes = await loadMeshesFromDisk(meshNamesInScene(scene));
      await pool.render(scene, meshes, { width: 64, height: 64 }).done;
      const correction = calibration.correction;
      const here = await estimateHere(pool, scene, meshes, width, height, { preview: true, calibration });
      if (!here?.measured) throw new Error(`${name}: the window would not have probed this render`);
      // The probe prices a sample of the scene at any size: scale the image to ASKED_SECONDS.
      const scale = Math.sqrt(ASKED_SECONDS / here.estimate(scene, width, height).seconds);
      const [askedWidth, askedHeight] = [Math.min(4096, Math.round(width * scale)), Math.min(4096, Math.round(height * scale))];
      const asked = here.estimate(scene, askedWidth, askedHeight);
      const smaller = lighterRenders(scene, askedWidth, askedHeight, here.estimate).find((option) => option.change === 'image-size');
      if (!asked.heavy || smaller?.change !== 'image-size')
        throw new Error(`${name}: estimated at ${asked.seconds.toFixed(0)} s, not heavy enough to suggest a smaller image`);
      const result = await pool.render(scene, meshes, { width: smaller.width, height: smaller.height }).done;
      if (result.cancelled) throw new Error(`${name}: the render was cancelled`);
      calibration.record(smaller.estimate.seconds / correction, result.ms);
      results.push({
        name,
        asked: { width: askedWidth, height: askedHeight, seconds: Math.round(asked.seconds) },
        suggested: {
          width: smaller.width,
          height: smaller.height,
          seconds: Number(smaller.estimate.seconds.toFixed(1)),
          modelSeconds: Number(estimateRender(scene, smaller.width, smaller.height, pool.size).seconds.toFixed(1)),
          realSeconds: Number((result.ms / 1000).toFixed(1)),
        },
        ratio: Number((result.ms / 1000 / smaller.estimate.seconds).toFixed(2)),
        correction: Number(correction.toFixed(2)),
      });
    }
  } finally {
    pool.dispose();
  }
  return results;
}

export function estimateRows(results: EstimateCase[]): [string, string, string][] {
  return results.map(({ name, asked, suggested, ratio, correction }) => [
    `estimate: ${name}, ${asked.width}×${asked.height} ~${asked.seconds} s → suggested ${suggested.width}×${suggested.height}`,
    `estimated ${suggested.seconds} s (model ${suggested.modelSeconds} s, correction ${correction}), real ${suggested.realSeconds} s: ${ratio}×`,
    `${(1 / ESTIMATE_RATIO_LIMIT).toFixed(2)}–${ESTIMATE_RATIO_LIMIT}×`,
  ]);
}

/** Whether every real time lies within a factor ESTIMATE_RATIO_LIMIT of its estimate. */
export function estimatesHold(results: EstimateCase[]): boolean {
  return results.every(({ ratio }) => ratio >= 1 / ESTIMATE_RATIO_LIMIT && ratio <= ESTIMATE_RATIO_LIMIT);
}
