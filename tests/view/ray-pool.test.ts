import { RAY_ARROWS_NAME, RAY_HIDDEN_NAME, RAY_STOPS_NAME } from '../../src/view/ray-extras.ts';
import { describe, expect, it } from 'vitest';
import { InstancedMesh, Matrix4, Raycaster, ShaderLib, Vector3, type InstancedBufferAttribute, type MeshBasicMaterial } from 'three';
import { DEFAULT_RAY_VIEW, type RayViewOptions } from '../../src/lab-state/lab-state.ts';
import { CONE_OPACITY, LOOP_PAUSE_S, RAY_CONES_NAME, RAY_CYLINDERS_NAME, RayPool } from '../../src/view/ray-pool.ts';
import {
  ALPHA_ATTRIBUTE,
  ARROW_AT,
  ARROW_AT_ATTRIBUTE,
  DASH_ATTRIBUTE,
  FULLY_GROWN,
  GROWTH_ATTRIBUTE,
  patchRayShader,
  STOP_ATTRIBUTE,
} from '../../src/view/ray-shader.ts';
import { hexToColor, RAY_DASHES, rayPalette } from '../../src/view/ray-palette.ts';
import { areaRay, ray, screen, syntheticScreen } from '../support/ray-fixtures.ts';

const options = (changes: Partial<RayViewOptions> = {}): RayViewOptions => ({ ...DEFAULT_RAY_VIEW, ...changes });

function meshes(pool: RayPool): InstancedMesh[] {
  return pool.object.children.filter((child): child is InstancedMesh => child instanceof InstancedMesh);
}

function parts(pool: RayPool) {
  const cylinders = pool.object.getObjectByName(RAY_CYLINDERS_NAME) as InstancedMesh;
  const cones = pool.object.getObjectByName(RAY_CONES_NAME) as InstancedMesh;
  const attribute = (mesh: InstancedMesh, name: string) => mesh.geometry.getAttribute(name) as InstancedBufferAttribute;
  return { cylinders, cones, attribute };
}

function transform(mesh: InstancedMesh, index: number, point: [number, number, number]): number[] {
  const matrix = new Matrix4();
  mesh.getMatrixAt(index, matrix);
  return new Vector3(...point).applyMatrix4(matrix).toArray();
}

function expectClose(actual: number[], expected: number[]): void {
  expect(actual.length).toBe(expected.length);
  actual.forEach((value, i) => expect(value).toBeCloseTo(expected[i], 5));
}

/** One pixel: a primary ray along −z from (0, 1, 5), 4 m, with a reflection up and an area-light cone. */
const oneTree = () =>
  screen(1, 1, () => [
    ray('primary', {
      origin: [0, 1, 5],
      direction: [0, 0, -1],
      length: 4,
      children: [
        ray('reflect', { origin: [0, 1, 1], direction: [0, 1, 0], length: 2, contribution: 0.2 }),
        areaRay('area-light', { origin: [0, 0, 0], contribution: 0.3 }),
      ],
    }),
  ]);

describe('RayPool instances', () => {
  it('draws one cylinder instance per ray and one cone per merged area node', () => {
    const pool = new RayPool();
    pool.update(oneTree(), options(), null);
    expect(pool.stats).toMatchObject({ rays: 2, cones: 1, drawCalls: 2 });
    const { cylinders, cones } = parts(pool);
    expect([cylinders.count, cones.count]).toEqual([2, 1]);
    pool.update(oneTree(), options({ showRays: false }), null);
    expect(pool.stats).toMatchObject({ rays: 0, cones: 0, drawCalls: 0 });
    expect(meshes(pool).every((mesh) => !mesh.visible)).toBe(true);
  });

  it('maps the unit cylinder onto each ray: origin, end, and radius across', () => {
    const pool = new RayPool();
    pool.update(oneTree(), options({ radius: 0.02 }), null);
    const { cylinders } = parts(pool);
    expectClose(transform(cylinders, 0, [0, 0, 0]), [0, 1, 5]);
    expectClose(transform(cylinders, 0, [0, 0, 1]), [0, 1, 1]);
    const side = new Vector3(...transform(cylinders, 0, [1, 0, 0.5]));
    expect(side.distanceTo(new Vector3(0, 1, 3))).toBeCloseTo(0.02, 6);
    // The reflection is vertical: the other helper axis still gives a proper basis.
    expectClose(transform(cylinders, 1, [0, 0, 1]), [0, 3, 1]);
    const across = new Vector3(...transform(cylinders, 1, [0, 1, 0.5]));
    expect(across.distanceTo(new Vector3(0, 2, 1))).toBeCloseTo(0.02, 6);
  });

  it('maps the unit pyramid onto each cone: apex at the hit point, base on the light corners', () => {
    const pool = new RayPool();
    pool.update(oneTree(), options(), null);
    const { cones } = parts(pool);
    expectClose(transform(cones, 0, [0, 0, 0]), [0, 0, 0]);
    expectClose(transform(cones, 0, [-1, -1, 1]), [-1, 3, -0.5]);
    expectClose(transform(cones, 0, [1, -1, 1]), [1, 3, -0.5]);
    expectClose(transform(cones, 0, [1, 1, 1]), [1, 3, 0.5]);
    expectClose(transform(cones, 0, [-1, 1, 1]), [-1, 3, 0.5]);
  });

  it('writes colour, alpha and growth per instance; cones at CONE_OPACITY of the rays', () => {
    const pool = new RayPool();
    pool.update(oneTree(), options({ transparency: 0.5, animate: true }), null);
    const { cylinders, cones, attribute } = parts(pool);
    const cyan = hexToColor(rayPalette('vrt').primary);
    const yellow = hexToColor(rayPalette('vrt').light);
    expectClose([...(cylinders.instanceColor?.array.slice(0, 3) ?? [])], cyan);
    expectClose([...(cones.instanceColor?.array.slice(0, 3) ?? [])], yellow);
    const alpha = 1 - 0.5 * 0.95;
    expect(attribute(cylinders, ALPHA_ATTRIBUTE).getX(1)).toBeCloseTo(alpha, 6);
    expect(attribute(cones, ALPHA_ATTRIBUTE).getX(0)).toBeCloseTo(alpha * CONE_OPACITY, 6);
    // Growth: (start, length) in metres of travel.
    expect([attribute(cylinders, GROWTH_ATTRIBUTE).getX(1), attribute(cylinders, GROWTH_ATTRIBUTE).getY(1)]).toEqual([4, 2]);
    expect([attribute(cones, GROWTH_ATTRIBUTE).getX(0), attribute(cones, GROWTH_ATTRIBUTE).getY(0)]).toEqual([4, 3]);
    // Only the instances in use are uploaded.
    expect(cylinders.instanceMatrix.updateRanges).toEqual([{ start: 0, count: 2 * 16 }]);
  });

  it('gives each cylinder its type’s dash pattern, in either palette: the primary ray solid, the reflected one dashed', () => {
    for (const colorBlindPalette of [false, true]) {
      const pool = new RayPool();
      pool.update(oneTree(), options({ colorBlindPalette }), null);
      const { cylinders, cones, attribute } = parts(pool);
      const dash = attribute(cylinders, DASH_ATTRIBUTE);
      expect([dash.getX(0), dash.getY(0)]).toEqual([...RAY_DASHES.primary]);
      expect([dash.getX(1), dash.getY(1)].map((v) => Math.fround(v))).toEqual(RAY_DASHES.reflect.map((v) => Math.fround(v)));
      expect(RAY_DASHES.reflect[0]).toBeGreaterThan(0);
      expect(dash.updateRanges).toEqual([{ start: 0, count: 2 * 2 }]);
      // Cones are light or shadow volumes, drawn whole.
      expect(cones.geometry.getAttribute(DASH_ATTRIBUTE)).toBeUndefined();
    }
  });

  it('draws the types that colour vision can confuse (light and refract, no-hit and refract) with different patterns', () => {
    const pattern = (key: keyof typeof RAY_DASHES) => RAY_DASHES[key].join('/');
    expect(pattern('light')).not.toBe(pattern('refract'));
    expect(pattern('no-hit')).not.toBe(pattern('refract'));
    expect(pattern('primary')).not.toBe(pattern('reflect'));
    expect(new Set(Object.values(RAY_DASHES).map((dash) => dash.join('/'))).size).toBeGreaterThanOrEqual(5);
  });

  it('lets opaque rays write depth and see-through ones not, without compiling a new program', () => {
    const pool = new RayPool();
    const material = () => parts(pool).cylinders.material as MeshBasicMaterial;
    pool.update(oneTree(), options(), null);
    const version = material().version;
    expect([material().transparent, material().depthWrite]).toEqual([true, true]);
    pool.update(oneTree(), options({ transparency: 0.2 }), null);
    expect([material().transparent, material().depthWrite]).toEqual([true, false]);
    pool.update(oneTree(), options(), null);
    expect(material().depthWrite).toBe(true);
    expect(material().version).toBe(version);
  });

  it("draws a chosen pixel's rays with arrowheads and their hidden parts, from the rays' own buffers, also after they grow", () => {
    const pool = new RayPool();
    const rays = syntheticScreen(1_000);
    pool.update(rays, options(), [0, 0]);
    const chosen = pool.stats.rays;
    expect(chosen).toBeGreaterThan(0);
    // Rays, arrowheads, hidden parts, and the plate of its blocked shadow ray.
    expect(pool.stats).toMatchObject({ arrows: chosen, drawCalls: 4 });
    const cylinders = () => pool.object.getObjectByName(RAY_CYLINDERS_NAME) as InstancedMesh;
    for (const name of [RAY_ARROWS_NAME, RAY_HIDDEN_NAME, RAY_STOPS_NAME]) {
      const extra = pool.object.getObjectByName(name) as InstancedMesh;
      expect(extra.instanceMatrix, name).toBe(cylinders().instanceMatrix);
      expect(extra.count, name).toBe(chosen);
    }
    pool.update(syntheticScreen(5_000), options(), null);
    expect(pool.stats).toMatchObject({ arrows: 0, drawCalls: 1 });
    pool.update(syntheticScreen(5_000), options(), [0, 0]);
    expect((pool.object.getObjectByName(RAY_ARROWS_NAME) as InstancedMesh).instanceMatrix).toBe(cylinders().instanceMatrix);
  });

  it("puts a ray's arrowhead a little past its middle and a normal's at its tip, in the buffer the arrows share", () => {
    const rays = screen(1, 1, () => [
      ray('primary', {
        origin: [0, 5, 0],
        direction: [0, -1, 0],
        length: 4,
        normal: [0, 1, 0],
        children: [ray('light', { untested: true, origin: [0, 1, 0], direction: [1, 0, 0] })],
      }),
    ]);
    const pool = new RayPool();
    pool.update(rays, options(), [0, 0]);
    const { cylinders, attribute } = parts(pool);
    const arrowAt = attribute(cylinders, ARROW_AT_ATTRIBUTE);
    expect([0, 1, 2].map((i) => arrowAt.getX(i))).toEqual([ARROW_AT, 1, ARROW_AT].map(Math.fround));
    expect(arrowAt.updateRanges).toEqual([{ start: 0, count: 3 }]);
    const arrows = pool.object.getObjectByName(RAY_ARROWS_NAME) as InstancedMesh;
    expect(arrows.geometry.getAttribute(ARROW_AT_ATTRIBUTE)).toBe(arrowAt);
    expect(pool.stats).toMatchObject({ rays: 3, arrows: 3 });
    // The direction to a light not tested is drawn in its sparse dots.
    const dash = attribute(cylinders, DASH_ATTRIBUTE);
    expect([dash.getX(2), dash.getY(2)]).toEqual(RAY_DASHES.untested.map(Math.fround));
    // No ray here is stopped: no stop plates, no draw call for them.
    expect((pool.object.getObjectByName(RAY_STOPS_NAME) as InstancedMesh).visible).toBe(false);
  });

  it('marks a blocked shadow ray: light paint in its gaps, and a stop plate at its end for a chosen pixel only', () => {
    const rays = screen(1, 1, () => [
      ray('primary', {
        origin: [0, 1, 5],
        direction: [0, 0, -1],
        length: 4,
        children: [ray('shadow', { origin: [0, 1, 1], direction: [0, 1, 0], length: 0.3 })],
      }),
    ]);
    const pool = new RayPool();
    pool.update(rays, options(), [0, 0]);
    const { cylinders, attribute } = parts(pool);
    const dash = attribute(cylinders, DASH_ATTRIBUTE);
    // A negative gap is painted, not left open (ray-shader.ts); the primary ray stays solid.
    expect([dash.getX(1), dash.getY(1)]).toEqual([RAY_DASHES.shadow[0], -RAY_DASHES.shadow[1]].map(Math.fround));
    expect([dash.getX(0), dash.getY(0)]).toEqual([0, 0]);
    const stop = attribute(cylinders, STOP_ATTRIBUTE);
    expect([stop.getX(0), stop.getX(1)]).toEqual([0, 1]);
    const stops = pool.object.getObjectByName(RAY_STOPS_NAME) as InstancedMesh;
    expect(stops.geometry.getAttribute(STOP_ATTRIBUTE)).toBe(stop);
    expect([stops.visible, stops.count, stops.instanceMatrix === cylinders.instanceMatrix]).toEqual([true, 2, true]);
    expect(pool.stats).toMatchObject({ drawCalls: 4 });
    // Every pixel's rays at once: no plates (nor arrowheads).
    pool.update(rays, options(), null);
    expect(stops.visible).toBe(false);
  });

  it('keeps one draw call for a whole screen of 1k, 10k and 50k rays', () => {
    const pool = new RayPool();
    const calls = [1_000, 10_000, 50_000].map((total) => {
      const rays = syntheticScreen(total);
      pool.update(rays, options(), null);
      return { rays: pool.stats.rays, meshes: meshes(pool).length, drawCalls: meshes(pool).filter((m) => m.visible && m.count > 0).length };
    });
    expect(calls.map((c) => c.rays)).toEqual([1_000, 10_000, 50_000]);
    expect(calls.every((c) => c.meshes === 5 && c.drawCalls === 1)).toBe(true);
  });

  it('pools its buffers: grows by doubling, never shrinks, and frees the outgrown mesh', () => {
    const pool = new RayPool();
    pool.update(syntheticScreen(1_000), options(), null);
    const small = parts(pool).cylinders;
    let disposed = false;
    small.addEventListener('dispose', () => (disposed = true));
    expect(small.instanceMatrix.count).toBe(1024);
    pool.update(syntheticScreen(3_000), options(), null);
    expect(parts(pool).cylinders.instanceMatrix.count).toBe(4096);
    expect(disposed).toBe(true);
    const big = parts(pool).cylinders;
    pool.update(syntheticScreen(500), options(), null);
    expect(parts(pool).cylinders).toBe(big);
    expect(big.instanceMatrix.count).toBe(4096);
    expect(big.count).toBe(500);
    // Per cylinder: matrix 16, colour 3, alpha 1, growth 2, dash 2, arrowhead place 1, stop 1; a cone has none of the last three.
    expect(pool.stats.instanceBytes).toBe((4096 * 26 + 256 * 22) * 4);
  });

  it('rebuilds 10k rays quickly (the goal is checked by the benchmark; logged here)', () => {
    const pool = new RayPool();
    const rays = syntheticScreen(10_000);
    pool.update(rays, options(), null);
    const times: number[] = [];
    for (let i = 0; i < 15; i++) {
      const started = performance.now();
      pool.update(rays, options({ transparency: (i % 2) * 0.3 }), null);
      times.push(performance.now() - started);
    }
    times.sort((a, b) => a - b);
    console.log(`RayPool rebuild of 10k rays: median ${times[7].toFixed(2)} ms`);
    expect(pool.stats.rays).toBe(10_000);
  });
});

describe('RayPool pieces', () => {
  it('draws its first instances alone, or any range of them, rays then cones, from its own buffers', () => {
    const pool = new RayPool();
    const rays = syntheticScreen(1000);
    pool.update(rays, options(), null);
    const { cylinders, attribute } = parts(pool);
    expect(pool.instances).toBe(1000);
    pool.drawFirst(300);
    expect([cylinders.count, pool.stats.rays]).toEqual([300, 300]);
    pool.drawFirst(null);
    expect(cylinders.count).toBe(1000);
    const piece = pool.piece(600, 500);
    const [pieceRays] = piece.children.filter((child): child is InstancedMesh => child instanceof InstancedMesh && child.name === RAY_CYLINDERS_NAME);
    expect(pieceRays.count).toBe(400);
    expect(pieceRays.material).toBe(cylinders.material);
    for (const index of [0, 399]) {
      expect(transform(pieceRays, index, [0, 0, 1])).toEqual(transform(cylinders, 600 + index, [0, 0, 1]));
      expect(pieceRays.geometry.getAttribute(DASH_ATTRIBUTE).getX(index)).toBe(attribute(cylinders, DASH_ATTRIBUTE).getX(600 + index));
    }
    // Pieces follow the order three.js draws the two meshes in (by creation; the cylinders' was made again when it grew).
    pool.update(oneTree(), options(), null);
    const { cylinders: rayMesh, cones: coneMesh } = parts(pool);
    const conesFirst = coneMesh.id < rayMesh.id;
    const kinds = [0, 1, 2].map((index) => {
      const drawn = pool.piece(index, 1).children.filter((child): child is InstancedMesh => child instanceof InstancedMesh && child.count > 0);
      expect(drawn).toHaveLength(1);
      return drawn[0].name;
    });
    expect(kinds).toEqual(conesFirst ? [RAY_CONES_NAME, RAY_CYLINDERS_NAME, RAY_CYLINDERS_NAME] : [RAY_CYLINDERS_NAME, RAY_CYLINDERS_NAME, RAY_CONES_NAME]);
    pool.drawFirst(1);
    expect([parts(pool).cylinders.count, parts(pool).cones.count]).toEqual(conesFirst ? [0, 1] : [1, 0]);
    pool.drawFirst(null);
    expect([parts(pool).cylinders.count, parts(pool).cones.count]).toEqual([2, 1]);
  });
});

describe('RayPool growth animation', () => {
  const travel = (pool: RayPool) => {
    const uniforms: Record<string, { value: number }> = {};
    const shader = { vertexShader: ShaderLib.basic.vertexShader, fragmentShader: ShaderLib.basic.fragmentShader, uniforms };
    (parts(pool).cylinders.material as MeshBasicMaterial).onBeforeCompile(shader as never, null as never);
    return uniforms.uTravel;
  };

  it('does no per-frame work when not animating: everything fully grown, tick says no more frames', () => {
    const pool = new RayPool();
    pool.update(oneTree(), options(), null);
    expect(pool.tick(1000)).toBe(false);
    expect(travel(pool).value).toBe(FULLY_GROWN);
  });

  it('grows at the animation speed from the first tick and stops asking for frames when done', () => {
    const pool = new RayPool();
    pool.update(oneTree(), options({ animate: true, animationSpeed: 2 }), null);
    expect(travel(pool).value).toBe(0);
    expect(pool.tick(5000)).toBe(true);
    expect(pool.tick(6000)).toBe(true);
    expect(travel(pool).value).toBeCloseTo(2, 9);
    // The tree ends at 4 + 3 m (the cone): 3.5 s at 2 m/s.
    expect(pool.tick(8400)).toBe(true);
    expect(pool.tick(8500)).toBe(false);
    expect(travel(pool).value).toBeCloseTo(7, 9);
  });

  it('loops with a pause, and keeps the rays where they were when only the speed changes', () => {
    const pool = new RayPool();
    const rays = oneTree();
    pool.update(rays, options({ animate: true, animationSpeed: 1, loop: true }), null);
    pool.tick(0);
    expect(pool.tick(7000 + LOOP_PAUSE_S * 1000 + 500)).toBe(true);
    expect(travel(pool).value).toBeCloseTo(0.5, 9);
    pool.update(rays, options({ animate: true, animationSpeed: 4, loop: true }), null);
    pool.tick(20_000);
    expect(travel(pool).value).toBeCloseTo(0.5, 9);
    pool.tick(20_500);
    expect(travel(pool).value).toBeCloseTo(2.5, 9);
  });

  it('restarts when new rays arrive or another pixel is selected', () => {
    const pool = new RayPool();
    const rays = oneTree();
    pool.update(rays, options({ animate: true }), null);
    pool.tick(0);
    pool.tick(1000);
    expect(travel(pool).value).toBeGreaterThan(0);
    pool.update(rays, options({ animate: true }), [0, 0]);
    expect(travel(pool).value).toBe(0);
    pool.tick(3000);
    expect(travel(pool).value).toBe(0);
  });

  it("patches three.js's basic shader with the growth and alpha attributes, failing loudly if its chunks change", () => {
    const shader = { vertexShader: ShaderLib.basic.vertexShader, fragmentShader: ShaderLib.basic.fragmentShader, uniforms: {} };
    const uniform = { value: 3 };
    const viewHeight = { value: 768 };
    patchRayShader(shader, uniform, viewHeight);
    expect(shader.vertexShader).toContain(`attribute vec2 ${GROWTH_ATTRIBUTE}`);
    expect(shader.vertexShader).toContain('vec4(0.0, 0.0, position.z * rayGrown, 1.0)');
    // A ray is placed in view space by its own code; three's projection stays for cones and arrowheads.
    expect(shader.vertexShader).toContain('gl_Position = projectionMatrix * mvPosition');
    expect(shader.vertexShader).toMatch(/#if defined\(RAY_CONE\) \|\| defined\(RAY_ARROW\) \|\| defined\(RAY_STOP\)\n#include <project_vertex>/);
    expect(shader.fragmentShader).toContain('diffuseColor.a *= vRayAlpha');
    expect(shader.vertexShader).toContain('position.x * max(rayRadius, 0.5 * 3.0 * rayPixel)');
    expect(shader.vertexShader).toContain(`attribute vec2 ${DASH_ATTRIBUTE}`);
    // An arrowhead's tip sits where its instance says (a ray's past the middle, a normal's at the end).
    expect(shader.vertexShader).toMatch(/#if defined\(RAY_ARROW\)\nattribute float aArrowAt;/);
    expect(shader.vertexShader).toContain(`vec4(0.0, 0.0, ${ARROW_AT_ATTRIBUTE} * rayGrown, 1.0)`);
    expect(shader.fragmentShader).toMatch(/mod\(vRayAlong, vRayDash\.x \+ abs\(vRayDash\.y\)\) > vRayDash\.x\) \{\n {2}if \(vRayDash\.y >= 0\.0\) discard;/);
    // A stop plate sits at its ray's end, shown only where the instance says and once the ray has grown there.
    expect(shader.vertexShader).toMatch(/#if defined\(RAY_STOP\)\nattribute float aStop;/);
    expect(shader.vertexShader).toContain(`float stopShown = ${STOP_ATTRIBUTE} * step(1.0, rayGrown);`);
    expect(shader.uniforms).toEqual({ uTravel: uniform, uViewHeight: viewHeight });
    expect(() => patchRayShader({ vertexShader: 'void main() {}', fragmentShader: '', uniforms: {} }, uniform, viewHeight)).toThrow(
      /begin_vertex|common|project_vertex/,
    );
  });
});

describe('RayPool.pick', () => {
  const pointer = (origin: [number, number, number], direction: [number, number, number]) =>
    new Raycaster(new Vector3(...origin), new Vector3(...direction).normalize());

  it('finds the ray under the pointer with its type, contribution, colour and pixel', () => {
    const rays = screen(2, 1, (x) => [ray('primary', { origin: [x * 10, 1, 5], direction: [0, 0, -1], length: 4, contribution: 0.5, color: [0.1, 0.2, 0.3] })]);
    const pool = new RayPool();
    pool.update(rays, options(), null);
    const hover = pool.pick(pointer([10, 5, 3], [0, -1, 0]));
    expect(hover).toMatchObject({ type: 'primary', contribution: 0.5, color: [0.1, 0.2, 0.3], pixel: [1, 0] });
    expect(hover?.node).toBe(rays.traces[1].rays[0]);
    expect(pool.pick(pointer([5, 5, 3], [0, -1, 0]))).toBeNull();
    // Past the ray's end (z < 1) there is nothing.
    expect(pool.pick(pointer([10, 5, 0.5], [0, -1, 0]))).toBeNull();
  });

  it("picks the nearest of two rays on the pointer's line, and never a hidden one", () => {
    const rays = screen(1, 1, () => [
      ray('primary', {
        origin: [-2, 1, 0],
        direction: [1, 0, 0],
        length: 4,
        children: [ray('reflect', { origin: [-2, 3, 0], direction: [1, 0, 0], length: 4, contribution: 0.001 })],
      }),
    ]);
    const pool = new RayPool();
    pool.update(rays, options(), null);
    expect(pool.pick(pointer([0, 10, 0], [0, -1, 0]))?.type).toBe('reflect');
    pool.update(rays, options({ hideNegligible: true }), null);
    expect(pool.pick(pointer([0, 10, 0], [0, -1, 0]))?.type).toBe('primary');
  });

  it('only picks what has grown so far', () => {
    const rays = screen(1, 1, () => [ray('primary', { origin: [0, 0, 0], direction: [1, 0, 0], length: 10 })]);
    const pool = new RayPool();
    pool.update(rays, options({ animate: true, animationSpeed: 1 }), null);
    pool.tick(0);
    pool.tick(3000);
    expect(pool.pick(pointer([2, 5, 0], [0, -1, 0]))).not.toBeNull();
    expect(pool.pick(pointer([5, 5, 0], [0, -1, 0]))).toBeNull();
  });

  it('says what a picked line is drawn as: a normal stands for the hit of its ray', () => {
    const primary = ray('primary', { origin: [0, 5, 0], direction: [0, -1, 0], length: 4, normal: [1, 0, 0], objectId: 'floor' });
    const pool = new RayPool();
    pool.update(
      screen(1, 1, () => [primary]),
      options(),
      [0, 0],
    );
    // The normal runs from (0, 1, 0) along +x.
    expect(pool.pick(pointer([0.2, 5, 0], [0, -1, 0]))).toMatchObject({ drawnAs: 'normal', type: 'primary', node: primary });
    expect(pool.pick(pointer([0, 3, 5], [0, 0, -1]))).toMatchObject({ drawnAs: 'primary', node: primary });
  });

  it('picks a cone anywhere inside it', () => {
    const rays = screen(1, 1, () => [ray('primary', { hit: true, length: 1, children: [areaRay('area-shadow', { contribution: 0 })] })]);
    const pool = new RayPool();
    pool.update(rays, options(), null);
    // Halfway up the cone (y = 1.5) its half-width is 0.5: x = 0.4 is inside, 0.8 outside.
    expect(pool.pick(pointer([0.4, 1.5, 10], [0, 0, -1]))?.type).toBe('area-shadow');
    expect(pool.pick(pointer([0.8, 1.5, 10], [0, 0, -1]))).toBeNull();
  });

  it('frees its GPU resources on dispose', () => {
    const pool = new RayPool();
    pool.update(oneTree(), options(), null);
    // The hidden parts share the rays' geometry: each resource once.
    const resources = new Set(meshes(pool).flatMap((mesh) => [mesh.geometry, mesh.material as MeshBasicMaterial]));
    const disposed = new Set<unknown>();
    for (const resource of resources) resource.addEventListener('dispose', () => disposed.add(resource));
    pool.dispose();
    expect(resources.size).toBe(9);
    expect(disposed).toEqual(resources);
    expect(pool.object.children).toEqual([]);
  });
});
