// The ray debugger's words, checked against what the tracer does: a glass hit whose ray is not
// refracted (total internal reflection) is not said to be split by Schlick, and "why is it dark"
// names the cause of a small A that the light's kind can have (a point light: only distance;
// an area light shines to one side of its panel, it has no cone). In English and in Dutch.
import { issueLine } from '../../../src/util/issue.ts';
import { readFileSync } from 'node:fs';
import { afterAll, beforeAll, describe, expect, it, vi } from 'vitest';
import { debugProgram } from '../../../src/debugger/debug-steps.ts';
import { parseLevel } from '../../../src/quest/level-schema.ts';
import { DEFAULT_SEED } from '../../../src/render/render-job.ts';
import type { Scene } from '../../../src/scene/scene.ts';
import { tracePixel } from '../../../src/tracer/trace-pixel.ts';
import { buildTracerScene } from '../../../src/tracer/tracer-scene.ts';
import { standInPage } from '../../support/page-locale.ts';

function levelScene(id: string): Scene {
  const parsed = parseLevel(JSON.parse(readFileSync(new URL(`../../../levels/${id}.level.json`, import.meta.url), 'utf8')));
  if (!parsed.ok) throw new Error(parsed.errors.map(issueLine).join('\n'));
  return parsed.level.scene;
}

describe('the ray debugger’s words', () => {
  let text: typeof import('../../../src/ui/lab/debugger/debugger-text.ts');
  let speak: (locale: 'en' | 'nl') => Promise<void>;

  beforeAll(async () => {
    speak = await standInPage();
    text = await import('../../../src/ui/lab/debugger/debugger-text.ts');
  });

  afterAll(() => {
    vi.unstubAllGlobals();
  });

  it('says Schlick splits a glass hit only where a refracted ray is traced, else total internal reflection with kr = 1', () => {
    const scene = levelScene('06-refraction');
    const tracer = buildTracerScene(scene, new Map());
    const [width, height] = scene.camera.pixels;
    let split = 0;
    let total = 0;
    for (let p = 0; p < width * height; p++) {
      const program = debugProgram(tracePixel(tracer, p % width, Math.floor(p / width), DEFAULT_SEED, { terms: true }), scene);
      for (const step of program.steps.filter((candidate) => candidate.kind === 'split')) {
        const refracted = step.ray!.children.some((child) => child.type === 'refract');
        const label = text.treeLabel(step, scene);
        if (refracted) {
          split++;
          expect(label).toMatch(/^Schlick: kr /);
          expect(text.stepText(step, scene)).toContain('Schlick splits');
        } else {
          total++;
          expect(step.ray!.children.filter((child) => child.type === 'reflect').map((child) => child.weight)).toEqual([1]);
          expect(label).toBe('Total internal reflection: kr 1, kt 0');
          expect(text.stepText(step, scene)).toContain('total internal reflection');
        }
      }
    }
    // Level 6's block traps a ray (its critical-angle task): both kinds are met.
    expect(split).toBeGreaterThan(0);
    expect(total).toBeGreaterThan(0);
  });

  it('gives the causes of a small A that each kind of light has', async () => {
    const scene = levelScene('10-area-lights');
    const area = scene.lights.find((light) => light.type === 'area')!;
    const point: Scene['lights'][number] = {
      id: 'bulb',
      name: { en: 'Bulb', nl: 'Peer' },
      type: 'point',
      position: [0, 3, 0],
      color: [1, 1, 1],
      intensity: 1,
      ambient: 0,
      diffuse: 1,
      specular: 1,
      distanceAttenuation: true,
    };
    const withPoint: Scene = { ...scene, lights: [...scene.lights, point] };
    expect(text.darkReasonText({ kind: 'outside-cone', lightId: area.id }, withPoint)).toMatch(
      /^The point is behind .*, which shines to one side only \(A = 0\)\.$/,
    );
    expect(text.darkReasonText({ kind: 'weakened', lightId: area.id, attenuation: 0.3 }, withPoint)).toContain('off to the side of the panel');
    expect(text.darkReasonText({ kind: 'weakened', lightId: 'bulb', attenuation: 0.3 }, withPoint)).toBe('Only part of Bulb arrives: A = 0.3 (its distance).');
    await speak('nl');
    expect(text.darkReasonText({ kind: 'weakened', lightId: 'bulb', attenuation: 0.3 }, withPoint)).toBe(
      'Maar een deel van Peer komt aan: A = 0,3 (door de afstand).',
    );
    expect(text.darkReasonText({ kind: 'outside-cone', lightId: area.id }, withPoint)).toContain('schijnt maar naar één kant');
    await speak('en');
  });
});
