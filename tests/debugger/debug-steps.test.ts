import { issueLine } from '../../src/util/issue.ts';
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { equationOf, pixelAverage, toByte } from '../../src/debugger/debug-equation.ts';
import { debugProgram, moveCursor, raysShownAt, stepCasting } from '../../src/debugger/debug-steps.ts';
import { PSEUDOCODE_LINES } from '../../src/debugger/pseudocode.ts';
import { isDark, whyDark } from '../../src/debugger/why-dark.ts';
import { parseLevel } from '../../src/quest/level-schema.ts';
import { loadMeshesFromDisk } from '../../src/scene/load-meshes-node.ts';
import { meshNamesInScene } from '../../src/scene/mesh-names.ts';
import type { Scene } from '../../src/scene/scene.ts';
import type { PixelTrace, RayNode } from '../../src/tracer/ray-tree.ts';
import { tracePixel } from '../../src/tracer/trace-pixel.ts';
import { buildTracerScene } from '../../src/tracer/tracer-scene.ts';
import { matte, pointLight, sceneFrom } from '../support/test-scene.ts';

function levelScene(file: string): Scene {
  const parsed = parseLevel(JSON.parse(readFileSync(new URL(`../../levels/${file}.level.json`, import.meta.url), 'utf8')));
  if (!parsed.ok) throw new Error(parsed.errors.map(issueLine).join('\n'));
  return parsed.level.scene;
}

async function tracesOf(scene: Scene): Promise<PixelTrace[]> {
  const tracer = buildTracerScene(scene, await loadMeshesFromDisk(meshNamesInScene(scene)));
  const [columns, rows] = scene.camera.pixels;
  return Array.from({ length: columns * rows }, (_, p) => tracePixel(tracer, p % columns, Math.floor(p / columns), 1, { terms: true }));
}

function depthFirst(nodes: RayNode[]): RayNode[] {
  return nodes.flatMap((node) => [node, ...depthFirst(node.children)]);
}

/** The first pixel whose first sample's tree has a ray of `type` below the root. */
function pixelWith(traces: PixelTrace[], test: (node: RayNode) => boolean): PixelTrace {
  const found = traces.find((trace) => depthFirst(trace.rays).some(test));
  if (!found) throw new Error('no pixel has such a ray');
  return found;
}

/** Adds the equation's terms in their order, as the tracer does. */
function addTerms(scene: Scene, hit: RayNode): number[] {
  const equation = equationOf(hit, scene);
  if (!equation) throw new Error('no equation');
  return [0, 1, 2].map((c) => equation.terms.reduce((sum, term) => sum + term.color[c], 0));
}

describe('the debugger’s steps over a pixel’s trace', async () => {
  const mirrorScene = levelScene('05-reflections');
  const glassScene = levelScene('06-refraction');
  const mirrorPixel = pixelWith(await tracesOf(mirrorScene), (node) => node.type === 'reflect' && node.hit);
  const glassPixel = pixelWith(await tracesOf(glassScene), (node) => node.type === 'refract');

  for (const [name, scene, trace] of [
    ['mirror', mirrorScene, mirrorPixel],
    ['glass', glassScene, glassPixel],
  ] as const) {
    it(`${name}: every ray is cast once, in the tracer's depth-first order, and the last step averages the pixel`, () => {
      const program = debugProgram(trace, scene);
      const cast = program.steps.filter((step) => step.kind === 'cast' || step.kind === 'light').map((step) => step.ray);
      expect(cast).toEqual(depthFirst(trace.rays));
      expect(program.rays).toEqual(cast);
      expect(program.steps[0]).toMatchObject({ kind: 'cast', line: 'trace-primary', ray: trace.rays[0], depth: 0 });
      expect(program.steps.at(-1)).toMatchObject({ kind: 'average', line: 'average', ray: null });
      expect(raysShownAt(program, program.steps.length - 1)).toHaveLength(cast.length);
      for (const step of program.steps) expect(PSEUDOCODE_LINES).toContain(step.line);
      // The rays drawn only grow, one per cast step.
      for (let i = 1; i < program.steps.length; i++) {
        const casts = program.steps[i].kind === 'cast' || program.steps[i].kind === 'light';
        expect(program.shownUpTo[i] - program.shownUpTo[i - 1]).toBe(casts ? 1 : 0);
      }
    });

    it(`${name}: every hit's equation adds up to its colour bit for bit, and the samples to the pixel`, () => {
      const program = debugProgram(trace, scene);
      const hits = program.steps.filter((step) => step.kind === 'shade').map((step) => step.ray as RayNode);
      expect(hits.length).toBeGreaterThan(1);
      for (const hit of hits) {
        const equation = equationOf(hit, scene);
        expect(addTerms(scene, hit)).toEqual(equation?.sum);
        expect(equation?.sum.map((value) => Math.min(1, Math.max(0, value)))).toEqual(hit.color);
        // Each child's term is what the child's own equation returned.
        for (const term of equation?.terms ?? []) {
          if ((term.kind === 'reflect' || term.kind === 'refract') && term.ray?.hit) expect(term.factors[1].value).toEqual(term.ray.color);
        }
      }
      const average = pixelAverage(program);
      const mean = [0, 1, 2].map((c) => Math.fround(average.parts.reduce((sum, part) => sum + part.share * part.ray.color[c], 0)));
      expect(mean).toEqual(trace.color);
      expect(average.rays).toBe(trace.rays.length);
    });
  }

  it('a mirror’s child is cast on the mirror line; a glass hit splits (Schlick) before its two rays, whose weights add up to 1', () => {
    const mirror = debugProgram(mirrorPixel, mirrorScene);
    expect(mirror.steps.find((step) => step.kind === 'cast' && step.ray?.type === 'reflect')).toMatchObject({ line: 'mirror', depth: 1 });
    const glass = debugProgram(glassPixel, glassScene);
    const split = glass.steps.findIndex((step) => step.kind === 'split');
    expect(glass.steps[split + 1]).toMatchObject({ kind: 'cast', line: 'glass', ray: { type: 'refract' } });
    const terms = glass.steps[split].ray?.terms;
    expect((terms?.refract?.weight ?? 0) + (terms?.reflect?.weight ?? 0)).toBeCloseTo(1, 12);
  });

  it('shadow rays light the "blocked" line, light rays the "lit" line; a hit returns on the return line', () => {
    const program = debugProgram(mirrorPixel, mirrorScene);
    for (const step of program.steps.filter((candidate) => candidate.kind === 'light')) {
      expect(step.line).toBe(step.ray?.type === 'shadow' || step.ray?.type === 'area-shadow' ? 'blocked' : 'lit');
      expect(step.hit?.children).toContain(step.ray);
    }
    const returns = program.steps.filter((step) => step.kind === 'return');
    expect(returns.map((step) => step.line)).toEqual(returns.map((step) => (step.ray?.hit ? 'return' : 'nearest-hit')));
  });

  it('clicking a term finds the step of its ray; the cursor stays within the steps', () => {
    const program = debugProgram(mirrorPixel, mirrorScene);
    const equation = equationOf(mirrorPixel.rays[0], mirrorScene);
    const reflect = equation?.terms.find((term) => term.kind === 'reflect');
    const at = stepCasting(program, reflect?.ray as RayNode);
    expect(program.steps[at]).toMatchObject({ kind: 'cast', ray: reflect?.ray });
    const last = program.steps.length - 1;
    expect(moveCursor(program, 0, 'back')).toBe(0);
    expect(moveCursor(program, 0, 'step')).toBe(1);
    expect(moveCursor(program, last, 'step')).toBe(last);
    expect(moveCursor(program, 5, 'reset')).toBe(0);
    expect(moveCursor(program, 0, 'end')).toBe(last);
  });

  it('supersampling: one tree per sample, stepped one after the other', async () => {
    const scene = { ...mirrorScene, settings: { ...mirrorScene.settings, supersampling: 2 } };
    const trace = (await tracesOf(scene))[mirrorPixel.pixel[1] * scene.camera.pixels[0] + mirrorPixel.pixel[0]];
    const program = debugProgram(trace, scene);
    const primaries = program.steps.filter((step) => step.kind === 'cast' && step.ray?.type === 'primary');
    expect(primaries.map((step) => step.sample)).toEqual([0, 1, 2, 3]);
    expect(toByte(trace.color[0])).toBe(Math.round(trace.color[0] * 255));
  });
});

describe('why is it dark here?', () => {
  const at = async (file: Record<string, unknown>) => {
    const scene = sceneFrom(file);
    const trace = tracePixel(buildTracerScene(scene, new Map()), 0, 0, 1, { terms: true });
    return whyDark(trace.rays[0], scene);
  };
  const floor = (material: Record<string, unknown> = {}) => ({ id: 'floor', shape: 'plane', scale: [20, 1, 20], material: matte([0.5, 0.5, 0.5], material) });
  const camera = { position: [0, 2, 0.001], target: [0, 0, 0], fov: 10, pixels: [1, 1] };

  it('says which object casts the shadow', async () => {
    const lid = { id: 'lid', shape: 'box', position: [0, 2.5, 0], scale: [0.5, 0.1, 0.5], material: matte([1, 1, 1]) };
    expect(await at({ camera, objects: [floor(), lid], lights: [pointLight([0, 3, 0])] })).toEqual([{ kind: 'shadow', lightId: 'lamp', blockerId: 'lid' }]);
  });

  it('says a light is behind the surface, or the point outside a spot light’s cone', async () => {
    expect(await at({ camera, objects: [floor()], lights: [pointLight([0, -3, 0])] })).toEqual([{ kind: 'facing-away', lightId: 'lamp' }]);
    const spot = { ...pointLight([0, 3, 0]), type: 'spot', rotation: [90, 0, 0], spotAngle: 30 };
    expect(await at({ camera, objects: [floor()], lights: [spot] })).toEqual([{ kind: 'outside-cone', lightId: 'lamp' }]);
  });

  it('says a mirror at the recursion depth sends no ray, and a ray that hit nothing shows the background', async () => {
    expect(await at({ camera, settings: { maxDepth: 0 }, objects: [floor({ specular: 0.5 })], lights: [pointLight([0, 3, 0])] })).toEqual([
      { kind: 'depth-limit', maxDepth: 0, objectId: 'floor', glass: false, specular: 0.5 },
    ]);
    expect(await at({ camera, settings: { maxDepth: 0 }, objects: [floor({ transparent: true })], lights: [pointLight([0, 3, 0])] })).toEqual([
      { kind: 'depth-limit', maxDepth: 0, objectId: 'floor', glass: true, specular: 0 },
    ]);
    expect(await at({ camera: { ...camera, target: [0, 4, 0] }, objects: [floor()], lights: [pointLight([0, 3, 0])] })).toEqual([{ kind: 'background' }]);
  });

  it('says nothing for a lit point', async () => {
    expect(await at({ camera, objects: [floor()], lights: [pointLight([0, 3, 0])] })).toEqual([]);
  });
});

describe('why is it dark here: only asked on a dark pixel, and a weakened light', () => {
  it('a pixel is dark when every channel is below 30 % of white', () => {
    expect(isDark([0.29, 0.1, 0])).toBe(true);
    expect(isDark([0.3, 0.1, 0])).toBe(false);
    expect(isDark([0.9, 0.6, 0.4])).toBe(false);
  });

  it('says how much of a light arrives when distance lets less than half of it through', async () => {
    const scene = sceneFrom({
      camera: { position: [0, 2, 0.001], target: [0, 0, 0], fov: 10, pixels: [1, 1] },
      objects: [{ id: 'floor', shape: 'plane', scale: [20, 1, 20], material: matte([0.5, 0.5, 0.5]) }],
      lights: [pointLight([0, 6, 0], { distanceAttenuation: true })],
    });
    const [reason] = whyDark(tracePixel(buildTracerScene(scene, new Map()), 0, 0, 1, { terms: true }).rays[0], scene);
    // 1 / (0.04 + 0.1·6 + 0.06·36): about 0.36 of the light arrives 6 m away.
    expect(reason).toMatchObject({ kind: 'weakened', lightId: 'lamp' });
    expect(reason.kind === 'weakened' && reason.attenuation).toBeCloseTo(1 / (0.04 + 0.6 + 0.06 * 36), 6);
  });
});
