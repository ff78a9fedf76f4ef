import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { loadMeshesFromDisk } from '../../src/scene/load-meshes-node.ts';
import { meshNamesInScene } from '../../src/scene/mesh-names.ts';
import type { Color, Scene } from '../../src/scene/scene.ts';
import { loadLevels } from '../../src/quest/level-index.ts';
import type { RayNode } from '../../src/tracer/ray-tree.ts';
import { renderTile } from '../../src/tracer/render-tile.ts';
import type { ShadingTerms } from '../../src/tracer/shading-terms.ts';
import { tracePixel } from '../../src/tracer/trace-pixel.ts';
import { buildTracerScene, type TracerScene } from '../../src/tracer/tracer-scene.ts';
import { matte, pointLight, sceneFrom, tracerSceneFrom } from '../support/test-scene.ts';

/**
 * The shading terms of ray-debugger spec §1 against the image, on every level's scene:
 * each hit's terms add up to its colour bit for bit, in the tracer's order; the colour is
 * their sum clamped; a reflect/refract term carries its child's colour; and tracing with
 * terms changes no ray and no colour.
 */

const levelsFolder = new URL('../../levels/', import.meta.url);
const catalog = loadLevels(readFileSync(new URL('index.json', levelsFolder), 'utf8'), (name) => readFileSync(new URL(name, levelsFolder), 'utf8'));
// The levels that start in Whitted mode: a path-mode scene has no shading terms (docs/path-tracing.md).
const levelScenes: [string, Scene][] = catalog.chapters.flatMap((chapter) =>
  chapter.entries.flatMap((entry) => (entry.ok && entry.level.scene.settings.integrator !== 'path' ? [[entry.id, entry.level.scene] as [string, Scene]] : [])),
);

/** ambient + Σ lights (ambient + diffuse + specular) + refract + reflect, in that order, per channel. */
function sumOfParts(terms: ShadingTerms): Color {
  return [0, 1, 2].map((c) => {
    let sum = terms.ambient[c];
    for (const light of terms.lights) {
      sum += light.ambient[c];
      sum += light.diffuse[c];
      sum += light.specular[c];
    }
    if (terms.refract) sum += terms.refract.color[c] * terms.refract.weight;
    if (terms.reflect) sum += terms.reflect.color[c] * terms.reflect.weight;
    return sum;
  }) as Color;
}

const clamp01 = (color: Color): Color => color.map((value) => Math.min(1, Math.max(0, value))) as Color;

function walk(nodes: RayNode[], visit: (node: RayNode, depth: number) => void, depth = 0): void {
  for (const node of nodes) {
    visit(node, depth);
    walk(node.children, visit, node.type === 'reflect' || node.type === 'refract' || node.type === 'primary' ? depth + 1 : depth);
  }
}

/** The tree without what tracing with terms adds: the hits' terms, the rays' weights and the light rays' parts. */
function withoutTerms(nodes: RayNode[]): RayNode[] {
  return nodes.map(({ terms: _terms, weight: _weight, parts: _parts, ...node }) => ({ ...node, children: withoutTerms(node.children) }));
}

async function tracerFor(scene: Scene): Promise<TracerScene> {
  return buildTracerScene(scene, await loadMeshesFromDisk(meshNamesInScene(scene)));
}

/** Checks every invariant on every pixel of the camera's screen; returns how many hits were checked. */
function checkScreen(tracer: TracerScene): number {
  const scene = tracer.source;
  const [width, height] = scene.camera.pixels;
  const image = renderTile(tracer, { x: 0, y: 0, width, height }, { imageWidth: width, imageHeight: height, seed: 1 });
  let hits = 0;
  for (let y = 0; y < height; y++) {
    for (let x = 0; x < width; x++) {
      const plain = tracePixel(tracer, x, y, 1);
      const traced = tracePixel(tracer, x, y, 1, { terms: true });
      // The image's colour, and the same rays as without terms.
      expect(traced.color).toEqual(Array.from(image.subarray((y * width + x) * 3, (y * width + x) * 3 + 3)));
      expect(withoutTerms(traced.rays)).toEqual(plain.rays);
      // The pixel is the mean of its samples' colours, as the renderer adds them.
      const mean = [0, 1, 2].map((c) => Math.fround(traced.rays.reduce((sum, root) => sum + root.color[c], 0) / traced.rays.length));
      expect(mean).toEqual(traced.color);
      for (const root of traced.rays) expect(root.weight).toBe(1 / traced.rays.length);
      walk(traced.rays, (node) => {
        const isSurfaceRay = node.type === 'primary' || node.type === 'reflect' || node.type === 'refract';
        if (!isSurfaceRay || !node.hit) {
          expect(node.terms).toBeUndefined();
          return;
        }
        const terms = node.terms;
        if (!terms) throw new Error(`a ${node.type} ray that hit ${node.objectId} has no terms`);
        hits++;
        expect(sumOfParts(terms)).toEqual(terms.sum);
        expect(clamp01(terms.sum)).toEqual(node.color);
        expect(terms.lights.map((light) => light.lightId)).toEqual(scene.lights.map((light) => light.id));
        for (const type of ['reflect', 'refract'] as const) {
          const children = node.children.filter((child) => child.type === type);
          expect(children.length).toBe(terms[type] ? 1 : 0);
          if (terms[type]) expect(terms[type].color).toEqual(children[0].color);
          // The child's weight is the term's: what the parent multiplies its colour by.
          if (terms[type]) expect(children[0].weight).toBe(terms[type].weight);
        }
        if (terms.reflect && terms.refract) expect(terms.reflect.weight + terms.refract.weight).toBeCloseTo(1, 12);
        for (const light of terms.lights) {
          // A light's rays carry its diffuse + specular, sample by sample.
          const rays = node.children.filter((child) => child.lightId === light.lightId);
          for (let c = 0; c < 3; c++) {
            expect(rays.reduce((sum, ray) => sum + ray.color[c], 0)).toBeCloseTo(light.diffuse[c] + light.specular[c], 12);
          }
          // Each ray's parts are its sample's diffuse and highlight: added in order, exactly the light's terms.
          expect(rays.reduce((sum, ray) => sum.map((value, c) => value + ray.parts!.diffuse[c]), [0, 0, 0])).toEqual(light.diffuse);
          expect(rays.reduce((sum, ray) => sum.map((value, c) => value + ray.parts!.specular[c]), [0, 0, 0])).toEqual(light.specular);
          for (const ray of rays) for (let c = 0; c < 3; c++) expect(ray.parts!.diffuse[c] + ray.parts!.specular[c]).toBeCloseTo(ray.color[c], 12);
          for (const factor of [light.attenuation, light.visibility, light.NdotL, light.RdotV]) expect(factor).toBeGreaterThanOrEqual(0);
          expect(light.visibility).toBeLessThanOrEqual(1);
          expect(light.NdotL).toBeLessThanOrEqual(1);
        }
      });
    }
  }
  return hits;
}

describe('shading terms on every level scene (ray-debugger spec §1)', () => {
  it('covers every level', () => {
    expect(catalog.errors).toEqual([]);
    expect(levelScenes.length).toBeGreaterThanOrEqual(20);
  });
  for (const [id, scene] of levelScenes) {
    it(`${id}: every hit's terms add up to its colour, which is the image's`, async () => {
      expect(checkScreen(await tracerFor(scene))).toBeGreaterThan(0);
    });
  }
  it('a scene with glass, a mirror, a 5×5 area light (merged cones), a spot and 2×2 jittered supersampling', async () => {
    const scene = sceneFrom({
      camera: { position: [0, 1.2, 4], target: [0, 0.4, 0], fov: 50, pixels: [10, 8] },
      settings: { supersampling: 2, samplePattern: 'jittered', maxDepth: 4, background: [0.6, 0.7, 0.9] },
      objects: [
        { id: 'floor', shape: 'plane', scale: [10, 1, 10], material: matte([0.8, 0.8, 0.8], { ambient: 0.1, specular: 0.2 }) },
        { id: 'glass', shape: 'sphere', position: [0.3, 0.5, 0.5], material: matte([1, 1, 1], { transparent: true, diffuse: 0.1, specular: 0.5 }) },
        { id: 'mirror', shape: 'box', position: [-0.8, 0.5, -0.5], rotation: [0, 30, 0], material: matte([0.2, 0.2, 0.2], { specular: 0.8 }) },
        { id: 'pillar', shape: 'cylinder', position: [1.2, 0.5, -0.8], material: matte([0.1, 0.8, 0.3], { specular: 0.3, shininess: 8 }) },
      ],
      lights: [
        { id: 'panel', type: 'area', position: [0, 3, 0], size: [1, 1], samples: 5, intensity: 0.8, ambient: 0.05 },
        { id: 'spot', type: 'spot', position: [2, 2.5, 1], rotation: [0, 0, 35], spotAngle: 50, angleAttenuation: 2, distanceAttenuation: true },
      ],
    });
    expect(checkScreen(await tracerFor(scene))).toBeGreaterThan(100);
  });
});

describe('shading terms of a rough (glossy) surface (distribution-effects)', () => {
  it("add its fan up to one term: the rays' shares summed, their colour the mean of those that left the surface", async () => {
    const scene = sceneFrom({
      camera: { position: [0, 1.2, 3], target: [0, 0.3, 0], fov: 45, pixels: [6, 4] },
      settings: { maxDepth: 2, background: [0.6, 0.7, 0.9] },
      objects: [
        { id: 'floor', shape: 'plane', scale: [10, 1, 10], material: matte([0.3, 0.3, 0.3], { specular: 0.7, roughness: 0.3, glossySamples: 3 }) },
        { id: 'ball', shape: 'sphere', position: [0, 0.5, -0.6], material: matte([0.9, 0.2, 0.1], { specular: 0.4, roughness: 0.2, glossySamples: 2 }) },
      ],
      lights: [pointLight([1, 3, 2])],
    });
    const tracer = await tracerFor(scene);
    const image = renderTile(tracer, { x: 0, y: 0, width: 6, height: 4 }, { imageWidth: 6, imageHeight: 4, seed: 1 });
    let fans = 0;
    for (let y = 0; y < 4; y++) {
      for (let x = 0; x < 6; x++) {
        const traced = tracePixel(tracer, x, y, 1, { terms: true });
        expect(traced.color).toEqual(Array.from(image.subarray((y * 6 + x) * 3, (y * 6 + x) * 3 + 3)));
        walk(traced.rays, (node) => {
          const fan = node.children.filter((child) => child.type === 'reflect');
          if (!node.terms || fan.length < 2) return;
          fans++;
          const { specular, glossySamples } = scene.objects.find((object) => object.id === node.objectId)!.material;
          const share = specular / (glossySamples * glossySamples);
          expect(fan).toHaveLength(glossySamples * glossySamples);
          for (const child of fan) expect(child.weight).toBe(share);
          const left = fan.filter((child) => !child.absorbed);
          const reflect = node.terms.reflect;
          if (left.length === 0) return expect(reflect).toBeNull();
          expect(reflect!.weight).toBeCloseTo(share * left.length, 12);
          for (let c = 0; c < 3; c++) {
            expect(reflect!.color[c]).toBeCloseTo(left.reduce((sum, child) => sum + child.color[c], 0) / left.length, 12);
            expect(sumOfParts(node.terms)[c]).toBeCloseTo(node.terms.sum[c], 12);
          }
          expect(clamp01(node.terms.sum)).toEqual(node.color);
        });
      }
    }
    expect(fans).toBeGreaterThan(4);
  });
});

/** The terms of the primary ray through pixel (x, y) of a 1×1 screen looking straight down at a plane. */
function primaryTerms(extra: {
  lights: unknown[];
  objects?: unknown[];
  material?: Record<string, unknown>;
  shadows?: boolean;
  maxDepth?: number;
}): ShadingTerms {
  const tracer = tracerSceneFrom({
    camera: { position: [0, 2, 0.001], target: [0, 0, 0], fov: 10, pixels: [1, 1] },
    settings: { shadows: extra.shadows ?? true, maxDepth: extra.maxDepth ?? 3 },
    objects: [
      { id: 'floor', shape: 'plane', scale: [20, 1, 20], material: matte([0.5, 0.4, 0.2], { ambient: 0.2, ...extra.material }) },
      ...(extra.objects ?? []),
    ],
    lights: extra.lights,
  });
  const root = tracePixel(tracer, 0, 0, 1, { terms: true }).rays[0];
  if (!root.terms) throw new Error('the primary ray has no terms');
  return root.terms;
}

describe('the factors of a hit', () => {
  it('a light straight above: N·L = 1, A = 1, S = 1, diffuse = I·kd·ld·Lc·C, ambient = ka·C and la·Lc·C', () => {
    const terms = primaryTerms({ lights: [pointLight([0, 3, 0], { intensity: 0.5, ambient: 0.1, color: [1, 0.5, 1] })] });
    const [light] = terms.lights;
    expect(terms.ambient).toEqual([0.5 * 0.2, 0.4 * 0.2, 0.2 * 0.2]);
    expect(light.ambient[1]).toBeCloseTo(0.1 * 0.5 * 0.4, 15);
    expect(light).toMatchObject({ lightId: 'lamp', attenuation: 1, visibility: 1, samples: 1 });
    expect(light.NdotL).toBeCloseTo(1, 6);
    expect(light.diffuse[0]).toBeCloseTo(0.5 * 0.5, 6);
    expect(light.diffuse[1]).toBeCloseTo(0.5 * 0.5 * 0.4, 6);
    expect(terms.reflect).toBeNull();
    expect(terms.depthLimited).toBe(false);
  });

  it('in shadow: S = 0 and no diffuse; with shadows off: S = 1', () => {
    // A lid between the light and the camera, which looks down from below it.
    const lid = { id: 'lid', shape: 'box', position: [0, 2.5, 0], scale: [0.5, 0.1, 0.5], material: matte([1, 1, 1]) };
    const shaded = primaryTerms({ lights: [pointLight([0, 3, 0])], objects: [lid] });
    expect(shaded.lights[0]).toMatchObject({ visibility: 0, diffuse: [0, 0, 0], specular: [0, 0, 0] });
    const unshaded = primaryTerms({ lights: [pointLight([0, 3, 0])], objects: [lid], shadows: false });
    expect(unshaded.lights[0].visibility).toBe(1);
    expect(unshaded.lights[0].diffuse[0]).toBeGreaterThan(0);
  });

  it('a light below the floor: N·L = 0 (facing away); a spot aimed elsewhere: A = 0', () => {
    expect(primaryTerms({ lights: [pointLight([0, -3, 0])] }).lights[0]).toMatchObject({ NdotL: 0, visibility: 1, diffuse: [0, 0, 0] });
    const spot = { ...pointLight([0, 3, 0]), type: 'spot', rotation: [90, 0, 0], spotAngle: 30, angleAttenuation: 1 };
    expect(primaryTerms({ lights: [spot] }).lights[0]).toMatchObject({ attenuation: 0, diffuse: [0, 0, 0] });
  });

  it('an area light half behind a wall: S is the share of its shadow rays that got through', () => {
    const panel = { id: 'panel', type: 'area', position: [0, 3, 0], size: [2, 2], samples: 4, intensity: 1, ambient: 0, angleAttenuation: 0 };
    // A thin wall under the panel's +x half, high above the floor.
    const wall = { id: 'wall', shape: 'box', position: [0.6, 2.5, 0], scale: [1.2, 0.05, 3], material: matte([1, 1, 1]) };
    const { lights } = primaryTerms({ lights: [panel], objects: [wall] });
    expect(lights[0].samples).toBe(16);
    expect(lights[0].visibility).toBe(0.5);
  });

  it('a mirror at the recursion depth says so, and one below it carries ks and its child', () => {
    const mirror = { specular: 0.6 };
    expect(primaryTerms({ lights: [pointLight([0, 3, 0])], material: mirror, maxDepth: 0 })).toMatchObject({ reflect: null, depthLimited: true });
    const terms = primaryTerms({ lights: [pointLight([0, 3, 0])], material: mirror, maxDepth: 2 });
    expect(terms.reflect?.weight).toBe(0.6);
    expect(terms.depthLimited).toBe(false);
  });

  it('a highlight: R·V = 1 under a light beside the camera, specular = I·ks·ls·Lc (not tinted by C)', () => {
    const terms = primaryTerms({ lights: [pointLight([0, 2, 0.001])], material: { specular: 0.5, shininess: 10 }, maxDepth: 0 });
    expect(terms.lights[0].RdotV).toBeCloseTo(1, 4);
    expect(terms.lights[0].specular[0]).toBeCloseTo(0.5, 3);
    expect(terms.lights[0].specular[2]).toBe(terms.lights[0].specular[0]);
  });
});
