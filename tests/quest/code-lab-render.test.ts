import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import type { LabOutcome, Rgb, Tolerance, Vec3 } from '../../src/quest/code-labs/code-lab-grading.ts';
import type { RenderLab } from '../../src/quest/code-labs/lab-render/lab-functions.ts';
import { labRenderScene } from '../../src/quest/code-labs/lab-render/lab-render-scene.ts';
import { pictureDifference } from '../../src/quest/code-labs/lab-render/picture-difference.ts';
import { maxPasses, renderWithLearner, type LabRenderResult } from '../../src/quest/code-labs/lab-render/render-passes.ts';
import { MIRROR_TOLERANCE } from '../../src/quest/code-labs/mirror-lab.ts';
import { PHONG_TOLERANCE, type PhongLight, type PhongMaterial } from '../../src/quest/code-labs/phong-lab.ts';
import { RAY_BOX_TOLERANCE } from '../../src/quest/code-labs/ray-box-lab.ts';
import { RAY_SPHERE_TOLERANCE } from '../../src/quest/code-labs/ray-sphere-lab.ts';
import { REFRACTION_TOLERANCE } from '../../src/quest/code-labs/refraction-lab.ts';
import { SHADOW_TOLERANCE, type Sphere } from '../../src/quest/code-labs/shadow-lab.ts';
import { parseLevelJson } from '../../src/quest/level-schema.ts';
import { toRgba8 } from '../../src/tracer/quantize.ts';

/*
 * Rendering with the learner's function, pass by pass. The learner's functions here are the
 * textbook's formulas, written as a learner would (not the tracer's code), and each typical
 * mistake; they are called as the sandbox calls them, on structured copies.
 */

const WIDTH = 160;
const HEIGHT = 120;

const dot = (a: Vec3, b: Vec3) => a.x * b.x + a.y * b.y + a.z * b.z;
const sub = (a: Vec3, b: Vec3): Vec3 => ({ x: a.x - b.x, y: a.y - b.y, z: a.z - b.z });
const combine = (a: Vec3, s: number, b: Vec3, t: number): Vec3 => ({ x: s * a.x + t * b.x, y: s * a.y + t * b.y, z: s * a.z + t * b.z });
const normalize = (a: Vec3) => combine(a, 1 / Math.sqrt(dot(a, a)), a, 0);

/** Shirley & Marschner §4.4.1; `signFlipped`: the discriminant taken as c − b² instead of b² − c. */
const hitSphereWith =
  (signFlipped = false) =>
  (origin: Vec3, direction: Vec3, center: Vec3, radius: number): number | null => {
    const oc = sub(origin, center);
    const b = dot(oc, direction);
    const c = dot(oc, oc) - radius * radius;
    const disc = signFlipped ? c - b * b : b * b - c;
    if (disc < 0) return null;
    let t = -b - Math.sqrt(disc);
    if (t <= 0) t = -b + Math.sqrt(disc);
    return t > 0 ? t : null;
  };

/** r = d − 2(d·n)n; `factor`: the 2 written as something else. */
const reflectWith =
  (factor = 2) =>
  (d: Vec3, n: Vec3): Vec3 =>
    combine(d, 1, n, -factor * dot(d, n));

/**
 * Snell's law in vector form with total internal reflection (Shirley & Marschner §13.1).
 * `noFlip`: inside the glass the outward normal is used as it is; `noTir`: no test of k < 0,
 * so the square root gives NaN.
 */
const refractWith =
  (wrong: { noFlip?: boolean; noTir?: boolean } = {}) =>
  (d: Vec3, outward: Vec3, ior: number): Vec3 | null => {
    const inside = dot(d, outward) > 0;
    const n = inside && !wrong.noFlip ? combine(outward, -1, outward, 0) : outward;
    const eta = inside ? ior : 1 / ior;
    const cosI = -dot(d, n);
    const k = 1 - eta * eta * (1 - cosI * cosI);
    if (k < 0 && !wrong.noTir) return null;
    return combine(d, eta, n, eta * cosI - Math.sqrt(k));
  };

/** Lambert + Phong for one light (the Phong lab's contract); `unclamped`: N·L and R·V used below 0 as they are. */
const shadeWith =
  (unclamped = false) =>
  (point: Vec3, n: Vec3, toEye: Vec3, light: PhongLight, material: PhongMaterial): Rgb => {
    const l = normalize(sub(light.position, point));
    const nDotL = dot(n, l);
    if (nDotL <= 0 && !unclamped) return { r: 0, g: 0, b: 0 };
    const r = combine(n, 2 * nDotL, l, -1);
    const rDotV = dot(r, toEye);
    const highlight = material.specular * Math.pow(unclamped ? rDotV : Math.max(rDotV, 0), material.shininess);
    const channel = (lc: number, c: number) => light.intensity * lc * (material.diffuse * nDotL * c + highlight);
    return { r: channel(light.color.r, material.color.r), g: channel(light.color.g, material.color.g), b: channel(light.color.b, material.color.b) };
  };

/** Anything between the point and the light; `anyT`: every hit on the line counts, behind the point and beyond the light too. */
const inShadowWith =
  (anyT = false) =>
  (point: Vec3, toLight: Vec3, distance: number, spheres: Sphere[]): boolean =>
    spheres.some(({ center, radius }) => {
      const oc = sub(point, center);
      const b = dot(oc, toLight);
      const disc = b * b - (dot(oc, oc) - radius * radius);
      if (disc < 0) return false;
      const roots = [-b - Math.sqrt(disc), -b + Math.sqrt(disc)];
      return roots.some((t) => anyT || (t > 0 && t < distance));
    });

/**
 * Kay & Kajiya's slab test (Shirley & Marschner §12.3.1): the entry t is the largest of the
 * slabs' near ts, the exit the smallest far t; from inside, the exit. `noSwap`: each slab's
 * ts taken as (min, max) in that order, wrong for a negative direction on that axis.
 */
const hitBoxWith =
  (noSwap = false) =>
  (origin: Vec3, direction: Vec3, boxMin: Vec3, boxMax: Vec3): number | null => {
    let near = -Infinity;
    let far = Infinity;
    for (const axis of ['x', 'y', 'z'] as const) {
      const t0 = (boxMin[axis] - origin[axis]) / direction[axis];
      const t1 = (boxMax[axis] - origin[axis]) / direction[axis];
      near = Math.max(near, noSwap ? t0 : Math.min(t0, t1));
      far = Math.min(far, noSwap ? t1 : Math.max(t0, t1));
    }
    if (!(near <= far) || far <= 0) return null;
    return near > 0 ? near : far;
  };

function levelScene(id: string) {
  const parsed = parseLevelJson(readFileSync(new URL(`../../levels/${id}.level.json`, import.meta.url), 'utf8'));
  if (!parsed.ok) throw new Error(`level ${id} does not parse`);
  return labRenderScene(parsed.level.scene);
}

const LEVELS: Record<RenderLab, { id: string; tolerance: Tolerance }> = {
  'ray-sphere': { id: '02-rays-from-the-camera', tolerance: RAY_SPHERE_TOLERANCE },
  'ray-box': { id: '15-bounding-boxes', tolerance: RAY_BOX_TOLERANCE },
  phong: { id: '03-shading', tolerance: PHONG_TOLERANCE },
  shadow: { id: '04-shadows', tolerance: SHADOW_TOLERANCE },
  mirror: { id: '05-reflections', tolerance: MIRROR_TOLERANCE },
  refraction: { id: '06-refraction', tolerance: REFRACTION_TOLERANCE },
};

/** Renders a lab's level with `learner` as the sandbox would run it; counts the batches asked. */
async function render(lab: RenderLab, learner: (...args: never[]) => unknown) {
  const scene = levelScene(LEVELS[lab].id);
  let batches = 0;
  const result = await renderWithLearner(
    scene,
    lab,
    LEVELS[lab].tolerance,
    (calls) => {
      batches++;
      const outcomes = calls.map((args): LabOutcome => {
        try {
          return { returned: structuredClone(learner(...(structuredClone(args) as never[]))) };
        } catch (error) {
          return { threw: String(error), line: null };
        }
      });
      return Promise.resolve({ outcomes });
    },
    WIDTH,
    HEIGHT,
  );
  return { result, batches, scene };
}

/** The pixels that differ between the learner's picture and the reference, as the panel shows them. */
function differing(result: LabRenderResult, settings: Parameters<typeof toRgba8>[3]): number {
  if (result.kind !== 'rendered') throw new Error(`not rendered: ${result.kind}`);
  const bytes = (rgb: Float32Array) => toRgba8(rgb, WIDTH, HEIGHT, settings);
  return pictureDifference(bytes(result.mine), bytes(result.reference)).differing;
}

const CORRECT: Record<RenderLab, (...args: never[]) => unknown> = {
  'ray-sphere': hitSphereWith(),
  'ray-box': hitBoxWith(),
  phong: shadeWith(),
  shadow: inShadowWith(),
  mirror: reflectWith(),
  refraction: refractWith(),
};

const WRONG: Record<RenderLab, (...args: never[]) => unknown> = {
  'ray-sphere': hitSphereWith(true),
  'ray-box': hitBoxWith(true),
  phong: shadeWith(true),
  shadow: inShadowWith(true),
  mirror: reflectWith(1),
  refraction: refractWith({ noFlip: true }),
};

describe('rendering a level with the learner’s function', () => {
  for (const lab of Object.keys(LEVELS) as RenderLab[]) {
    it(`${lab}: a correct function renders the reference exactly, a typical wrong one visibly differs`, async () => {
      const right = await render(lab, CORRECT[lab]);
      expect(right.result.kind).toBe('rendered');
      expect(differing(right.result, right.scene.source.settings)).toBe(0);
      // The learner's function was asked, not skipped: at least one batch of calls.
      expect(right.batches).toBeGreaterThan(0);
      const wrong = await render(lab, WRONG[lab]);
      expect(differing(wrong.result, wrong.scene.source.settings)).toBeGreaterThan(100);
    });
  }

  it('asks in a bounded number of passes, one batch fewer than the passes', async () => {
    for (const lab of ['ray-sphere', 'mirror', 'refraction'] as const) {
      const { result, batches, scene } = await render(lab, WRONG[lab]);
      if (result.kind !== 'rendered') throw new Error(result.kind);
      expect(result.passes).toBeLessThanOrEqual(maxPasses(scene.source.settings.maxDepth));
      expect(batches).toBe(result.passes - 1);
      expect(result.calls).toBeGreaterThan(WIDTH * HEIGHT * 0.2);
    }
  });

  it('a wrong function’s rays that depend on its own answers take more than one batch', async () => {
    // Level 06's glass: a refracted ray's refraction is only asked once the first is known.
    const { result, batches } = await render('refraction', WRONG.refraction);
    expect(result.kind).toBe('rendered');
    expect(batches).toBeGreaterThan(1);
  });

  it('stops at an answer it cannot use, with that call as the grader words it', async () => {
    const { result } = await render('mirror', () => undefined);
    expect(result).toMatchObject({ kind: 'bad-answer', failure: { reason: 'wrong-type', got: undefined } });
    const thrown = await render('ray-sphere', () => {
      throw new Error('oops');
    });
    expect(thrown.result).toMatchObject({ kind: 'bad-answer', failure: { reason: 'threw' } });
    // No total internal reflection: the glass block's steep rays come back as NaN.
    const noTir = await render('refraction', refractWith({ noTir: true }));
    expect(noTir.result).toMatchObject({ kind: 'bad-answer', failure: { reason: 'not-a-number', got: { x: NaN, y: NaN, z: NaN } } });
  });

  it('stops when the sandbox gives no answers', async () => {
    const scene = levelScene('02-rays-from-the-camera');
    const result = await renderWithLearner(scene, 'ray-sphere', RAY_SPHERE_TOLERANCE, () => Promise.resolve({ reason: 'timeout' }), 40, 30);
    expect(result).toEqual({ kind: 'no-answers', reason: 'timeout' });
  });
});

describe('a lab render on the page', () => {
  it('lets timers and input run between bands of rows instead of holding the thread for a whole pass', async () => {
    const scene = levelScene('02-rays-from-the-camera');
    let turns = 0;
    let rendering = true;
    const count = () => {
      if (!rendering) return;
      turns++;
      setTimeout(count, 0);
    };
    setTimeout(count, 0);
    const result = await renderWithLearner(scene, 'ray-sphere', RAY_SPHERE_TOLERANCE, () => Promise.resolve({ reason: 'timeout' }), 160, 120);
    rendering = false;
    expect(result.kind).toBe('no-answers');
    // The reference and the first pass: 2 × 120 rows in bands of 8, so the page had a turn about 30 times.
    expect(turns).toBeGreaterThanOrEqual(20);
  });
});

describe('the difference picture', () => {
  it('is black where the pictures agree and bright where they differ, and counts the pixels', () => {
    const mine = new Uint8ClampedArray([10, 20, 30, 255, 100, 100, 100, 255, 0, 0, 0, 255]);
    const reference = new Uint8ClampedArray([10, 20, 30, 255, 101, 100, 90, 255, 0, 0, 0, 255]);
    const { rgba, differing: count } = pictureDifference(mine, reference);
    expect(count).toBe(1);
    expect([...rgba]).toEqual([0, 0, 0, 255, 64, 0, 80, 255, 0, 0, 0, 255]);
  });
});
