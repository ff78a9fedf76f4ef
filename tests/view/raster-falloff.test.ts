import { MeshPhongMaterial, PointLight, ShaderChunk, ShaderLib, SpotLight } from 'three';
import { describe, expect, it } from 'vitest';
import { defaultScene } from '../../src/scene/scene-defaults.ts';
import type { Light, Scene } from '../../src/scene/scene.ts';
import { angleAttenuation, distanceAttenuation } from '../../src/tracer/attenuation.ts';
import { ANGLE_FALLOFF_GLSL, DISTANCE_FALLOFF_GLSL, FOLLOWS_DISTANCE, tracerLightsChunk, useTracerFalloff } from '../../src/view/raster-falloff.ts';
import { RasterLights } from '../../src/view/raster-lights.ts';

/**
 * Runs a GLSL function of raster-falloff.ts as JavaScript: its body is if/return statements
 * over its parameters, with GLSL's pow as Math.pow. This is the shader's own text, not a copy.
 */
function runGlsl(source: string): (...args: number[]) => number {
  const match = /^float \w+\(([^)]*)\) \{\n([\s\S]*)\n\}$/.exec(source);
  if (!match) throw new Error(`not a one-function GLSL source: ${source}`);
  const params = match[1]!.split(',').map((p) => p.trim().split(/\s+/).at(-1)!);
  return new Function('pow', ...params, match[2]!).bind(null, Math.pow) as (...args: number[]) => number;
}

describe("the 3D view shades with the tracer's light fall-off", () => {
  it("distance attenuation: the shader's function is the tracer's 1 / (0.04 + 0.1·d + 0.06·d²) when decay says so, else 1", () => {
    const raster = runGlsl(DISTANCE_FALLOFF_GLSL);
    for (const d of [0, 0.25, 1, 2.2, 3.3, 5, 12.5, 40]) {
      expect(raster(d, 0, FOLLOWS_DISTANCE)).toBeCloseTo(distanceAttenuation(d), 12);
      expect(raster(d, 7, 0)).toBe(1);
    }
    // The 1/d² fall-off three.js would have used differs: at 1 m it gives 1, the tracer 5.
    expect(raster(1, 0, FOLLOWS_DISTANCE)).toBeCloseTo(5, 12);
  });

  it('angle attenuation: cos(α)^p inside the cone, 0 outside or behind, as the tracer', () => {
    const raster = runGlsl(ANGLE_FALLOFF_GLSL);
    for (const halfAngle of [10, 22.5, 60, 90]) {
      const cone = Math.cos((halfAngle * Math.PI) / 180);
      for (const p of [0, 1, 4, 16, 64]) {
        for (const alpha of [0, 5, 21, 30, 59, 61, 89, 95, 180]) {
          const cosAlpha = Math.cos((alpha * Math.PI) / 180);
          expect(raster(cone, p, cosAlpha)).toBeCloseTo(angleAttenuation(cosAlpha, cone, p), 12);
        }
      }
    }
  });

  it("the lights chunk swaps three.js's fall-off for the tracer's and its spot lights call the tracer's cone", () => {
    const chunk = tracerLightsChunk();
    expect(chunk.match(/float getDistanceAttenuation\(/g)).toHaveLength(1);
    expect(chunk).toContain(DISTANCE_FALLOFF_GLSL);
    expect(chunk).toContain(ANGLE_FALLOFF_GLSL);
    expect(chunk).not.toContain('pow( lightDistance, decayExponent )');
    expect(chunk).toContain('getTracerAngleAttenuation( spotLight.coneCos, spotLight.distance, angleCos )');
    expect(chunk).not.toContain('getSpotAttenuation( spotLight.coneCos');
    // Everything else of three.js's chunk stays.
    expect(chunk).toContain('void getPointLightInfo(');
    expect(() => tracerLightsChunk('float somethingElse() { return 1.0; }')).toThrow(/three\.js lights_pars_begin changed/);
  });

  it("a patched material compiles the tracer's chunk into its fragment shader only", () => {
    const material = new MeshPhongMaterial();
    useTracerFalloff(material);
    const shader = { vertexShader: ShaderLib.phong.vertexShader, fragmentShader: ShaderLib.phong.fragmentShader, uniforms: {}, defines: {} };
    expect(shader.fragmentShader).toContain('#include <lights_pars_begin>');
    material.onBeforeCompile(shader as never, undefined as never);
    expect(shader.fragmentShader).not.toContain('#include <lights_pars_begin>');
    expect(shader.fragmentShader).toContain(DISTANCE_FALLOFF_GLSL);
    expect(shader.vertexShader).toBe(ShaderLib.phong.vertexShader);
    expect(material.customProgramCacheKey()).not.toBe(new MeshPhongMaterial().customProgramCacheKey());
    expect(ShaderChunk.lights_pars_begin).toContain('pow( lightDistance, decayExponent )');
  });
});

describe("raster lights carry the tracer's values", () => {
  function lightsOf(scene: Scene): (PointLight | SpotLight)[] {
    const raster = new RasterLights();
    raster.sync(scene);
    const found: (PointLight | SpotLight)[] = [];
    raster.group.traverse((o) => {
      if (o instanceof PointLight || o instanceof SpotLight) found.push(o);
    });
    return found;
  }

  function withLights(lights: Partial<Light>[]): Scene {
    const scene = defaultScene();
    const base = scene.lights[0]!;
    return { ...scene, lights: lights.map((l, i) => ({ ...base, id: `l${i}`, ...l }) as Light) };
  }

  it('distance attenuation on or off is the decay flag; the intensity is π·I·ld wherever the camera looks', () => {
    const [off, on] = lightsOf(
      withLights([
        { type: 'point', intensity: 2, diffuse: 0.5 },
        { type: 'point', intensity: 2, diffuse: 0.5, distanceAttenuation: true },
      ]),
    );
    expect(off!.decay).toBe(0);
    expect(on!.decay).toBe(FOLLOWS_DISTANCE);
    expect(on!.intensity).toBeCloseTo(Math.PI, 12);
    expect(off!.intensity).toBeCloseTo(Math.PI, 12);
    expect(on!.distance).toBe(0);
  });

  it("a spot light's cone is the tracer's: half its angle, no penumbra, p in distance", () => {
    const [spot, area] = lightsOf(
      withLights([
        { type: 'spot', spotAngle: 60, angleAttenuation: 16, rotation: [0, 0, 0] } as Partial<Light>,
        { type: 'area', angleAttenuation: 3, rotation: [0, 0, 0], size: [1, 1], samples: 3, shape: 'rectangle' } as Partial<Light>,
      ]),
    ) as SpotLight[];
    expect(spot!.angle).toBeCloseTo(Math.PI / 6, 12);
    expect(spot!.penumbra).toBe(0);
    expect(spot!.distance).toBe(16);
    expect(area!.angle).toBeCloseTo(Math.PI / 2, 12);
    expect(area!.distance).toBe(3);
  });
});
