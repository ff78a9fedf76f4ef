import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import type { Rgb, Vec3 } from '../../src/quest/code-labs/code-lab-grading.ts';
import { PHONG_EDGES } from '../../src/quest/code-labs/phong-edges.ts';
import { PHONG_TOLERANCE, phongCases, tracerPhong, type PhongLight, type PhongMaterial } from '../../src/quest/code-labs/phong-lab.ts';
import { loadLevels } from '../../src/quest/level-index.ts';
import type { Scene } from '../../src/scene/scene.ts';
import type { RayNode } from '../../src/tracer/ray-tree.ts';
import { tracePixel } from '../../src/tracer/trace-pixel.ts';
import { buildTracerScene } from '../../src/tracer/tracer-scene.ts';
import { gradeFunction } from '../support/code-lab-grade.ts';

const dot = (a: Vec3, b: Vec3) => a.x * b.x + a.y * b.y + a.z * b.z;
const unit = (a: Vec3): Vec3 => {
  const l = Math.hypot(a.x, a.y, a.z);
  return { x: a.x / l, y: a.y / l, z: a.z / l };
};

/** How a learner might write it; `mistake` names one way of getting it wrong. */
const shadeWith =
  (mistake: 'none' | 'cos-not-clamped' | 'reflect-wrong-way' | 'no-specular') =>
  (point: Vec3, normal: Vec3, toEye: Vec3, light: PhongLight, material: PhongMaterial): Rgb => {
    const l = unit({ x: light.position.x - point.x, y: light.position.y - point.y, z: light.position.z - point.z });
    const nDotL = dot(normal, l);
    if (nDotL <= 0 && mistake !== 'cos-not-clamped') return { r: 0, g: 0, b: 0 };
    // R = 2(N·L)N − L; the wrong way round is L − 2(N·L)N, the reflection of L instead of −L.
    const sign = mistake === 'reflect-wrong-way' ? -1 : 1;
    const r = { x: sign * (2 * nDotL * normal.x - l.x), y: sign * (2 * nDotL * normal.y - l.y), z: sign * (2 * nDotL * normal.z - l.z) };
    const highlight = mistake === 'no-specular' ? 0 : material.specular * Math.pow(Math.max(dot(r, toEye), 0), material.shininess);
    const channel = (lc: number, c: number) => light.intensity * lc * (material.diffuse * nDotL * c + highlight);
    return { r: channel(light.color.r, material.color.r), g: channel(light.color.g, material.color.g), b: channel(light.color.b, material.color.b) };
  };

const grade = (shade: ReturnType<typeof shadeWith>, seed = 3) => gradeFunction(phongCases(PHONG_EDGES, 300, seed), PHONG_TOLERANCE, shade);

describe('the Phong lab', () => {
  it('passes a correct function (Math.pow, another order of operations) with any seed', () => {
    for (const seed of [1, 3, 43, 9999]) expect(grade(shadeWith('none'), seed)).toMatchObject({ firstFailure: null, passed: 304 });
  });

  it('has cases with the light behind, a full highlight and a partial one', () => {
    const [behind, inHighlight, beside] = phongCases(PHONG_EDGES, 0, 1).map((labCase) => labCase.expected as Rgb);
    expect(behind).toEqual({ r: 0, g: 0, b: 0 });
    // V = R: ks·1ⁿ on top of kd·cos45°·C.
    expect(inHighlight.b).toBeCloseTo(0.1 * Math.SQRT1_2 + 0.5, 12);
    expect(beside.b).toBeCloseTo(0.1 * Math.SQRT1_2 + 0.5 * Math.cos((20 * Math.PI) / 180) ** 10, 12);
  });

  it.each([
    ['a cosine not clamped', 'cos-not-clamped', 'phong-light-behind'],
    ['the reflection vector the wrong way round', 'reflect-wrong-way', 'phong-in-the-highlight'],
    ['no specular term', 'no-specular', 'phong-in-the-highlight'],
  ] as const)('fails a function with %s on a named case', (_name, mistake, kind) => {
    const report = grade(shadeWith(mistake));
    expect(report.firstFailure).toMatchObject({ reason: 'wrong-value' });
    expect(report.firstFailure?.labCase.kind).toBe(kind);
  });
});

describe('the Phong lab’s reference is the tracer’s shading', () => {
  it('equals the diffuse + specular the tracer records for its hits in level 03 (a coloured, brighter lamp, 24×16 pixels)', async () => {
    const levelsFolder = new URL('../../levels/', import.meta.url);
    const catalog = loadLevels(readFileSync(new URL('index.json', levelsFolder), 'utf8'), (name) => readFileSync(new URL(name, levelsFolder), 'utf8'));
    const entry = catalog.chapters.flatMap((chapter) => chapter.entries).find((candidate) => candidate.id === '03-shading');
    if (!entry?.ok) throw new Error('level 03 does not load');
    const level = entry.level.scene;
    const scene: Scene = {
      ...level,
      camera: { ...level.camera, pixels: [24, 16] },
      lights: level.lights.map((lamp) => ({ ...lamp, color: [1, 0.8, 0.6], intensity: 1.5 })),
    };
    const [lamp] = scene.lights;
    expect(lamp).toMatchObject({ type: 'point', diffuse: 1, specular: 1, distanceAttenuation: false });
    const tracer = buildTracerScene(scene, new Map());
    const light: PhongLight = { position: { x: lamp.position[0], y: lamp.position[1], z: lamp.position[2] }, color: { r: 1, g: 0.8, b: 0.6 }, intensity: 1.5 };
    const [width, height] = scene.camera.pixels;
    let compared = 0;
    let highlights = 0;
    for (let y = 0; y < height; y++)
      for (let x = 0; x < width; x++) {
        const primary: RayNode | undefined = tracePixel(tracer, x, y, 1, { terms: true }).rays[0];
        const terms = primary?.terms?.lights[0];
        // Only lit hits: a blocked shadow ray makes S = 0, which the lab leaves out.
        if (!primary?.normal || !terms || terms.visibility !== 1) continue;
        const { origin: o, direction: d, length: t, normal: n } = primary;
        const point = { x: o[0] + t * d[0], y: o[1] + t * d[1], z: o[2] + t * d[2] };
        const object = scene.objects.find((candidate) => candidate.id === primary.objectId);
        if (!object) throw new Error(`no object ${primary.objectId}`);
        const { color, diffuse, specular, shininess } = object.material;
        const material: PhongMaterial = { color: { r: color[0], g: color[1], b: color[2] }, diffuse, specular, shininess };
        const expected = tracerPhong(point, { x: n[0], y: n[1], z: n[2] }, { x: -d[0], y: -d[1], z: -d[2] }, light, material);
        (['r', 'g', 'b'] as const).forEach((channel, c) => expect(expected[channel]).toBeCloseTo(terms.diffuse[c] + terms.specular[c], 12));
        compared++;
        if (terms.specular[0] > 1e-3) highlights++;
      }
    expect(compared).toBeGreaterThan(100);
    expect(highlights).toBeGreaterThan(5);
  });
});
