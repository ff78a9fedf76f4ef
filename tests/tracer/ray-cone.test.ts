import { Vector3 } from 'three';
import { describe, expect, it } from 'vitest';
import type { Intersectable } from '../../src/tracer/intersectable.ts';
import { TracerLight } from '../../src/tracer/lights.ts';
import { hashKey, RandomStream } from '../../src/tracer/sampler.ts';
import { RayCone } from '../../src/tracer/ray-cone.ts';
import { buildTracerScene } from '../../src/tracer/tracer-scene.ts';
import { objectGridScene } from '../../bench/object-grid-scene.ts';
import { tracerSceneFrom } from '../support/test-scene.ts';

const random = new RandomStream().reset(hashKey(31));
const between = (low: number, high: number) => low + (high - low) * random.next();

const boxOf = ({ worldBounds: { min, max } }: Intersectable) => new Float64Array([min.x, min.y, min.z, max.x, max.y, max.z]);

function areaLight(shape: 'rectangle' | 'disc', samples: number): TracerLight {
  return new TracerLight(
    tracerSceneFrom({
      lights: [
        {
          id: 'panel',
          type: 'area',
          shape,
          samples,
          position: [between(-3, 3), between(2, 5), between(-3, 3)],
          rotation: [between(-60, 60), between(0, 90), between(-60, 60)],
          size: [between(0.2, 3), between(0.2, 3)],
        },
      ],
    }).source.lights[0],
  );
}

describe('the shadow cone from a hit point to an area light', () => {
  it('never excludes a box that a shadow ray toward the light passes through, up to both of its ends', () => {
    const epsilon = 1e-4;
    const cone = new RayCone();
    const sample = new Vector3();
    const onRay = new Vector3();
    const tiny = 1e-9;
    let tested = 0;
    for (let trial = 0; trial < 200; trial++) {
      const light = areaLight(trial % 2 === 0 ? 'rectangle' : 'disc', 3);
      const point = new Vector3(between(-4, 4), between(-1, 6), between(-4, 4));
      cone.toLight(point, light, 4 * epsilon);
      for (let s = 0; s < light.sampleCount; s++) {
        light.samplePoint(s % light.samplesPerSide, Math.floor(s / light.samplesPerSide), random, sample);
        const toLight = sample.clone().sub(point);
        const distance = toLight.length();
        toLight.normalize();
        // As the integrator casts it: from ε off the point (any side), to ε short of the light.
        const origin = point.clone().addScaledVector(new Vector3(between(-1, 1), between(-1, 1), between(-1, 1)).normalize(), epsilon);
        for (const t of [0, distance - epsilon, between(0, distance - epsilon)]) {
          onRay.copy(origin).addScaledVector(toLight, t);
          const box = new Float64Array([onRay.x - tiny, onRay.y - tiny, onRay.z - tiny, onRay.x + tiny, onRay.y + tiny, onRay.z + tiny]);
          expect(cone.excludes(box, 0)).toBe(false);
          tested++;
        }
      }
    }
    expect(tested).toBe(200 * 9 * 3);
  });

  it('above a crowd of objects keeps a few of the many the box around point and light overlaps', () => {
    const scene = buildTracerScene(objectGridScene(16), new Map());
    const light = scene.lights.find((l) => l.type === 'area')!;
    const top = scene.shapes[8 * 16 + 8].worldBounds; // an object in the middle of the grid
    const point = new Vector3((top.min.x + top.max.x) / 2, top.max.y, (top.min.z + top.max.z) / 2);
    const reach = light.extent.clone().expandByPoint(point);
    const inBox = scene.shapes.filter((shape) => shape.worldBounds.intersectsBox(reach));
    const cone = new RayCone().toLight(point, light, 4 * scene.epsilon);
    const inCone = inBox.filter((shape) => !cone.excludes(boxOf(shape), 0));
    expect(inBox.length).toBeGreaterThan(20);
    expect(inCone.length).toBeLessThan(inBox.length / 4);
    expect(inCone.length).toBeGreaterThan(0); // the object under the point itself touches the apex
  });
});
