import { BoxGeometry, Mesh, MeshBasicMaterial, Vector3 } from 'three';
import { describe, expect, it } from 'vitest';
import { DEFAULT_SEED } from '../../src/render/render-job.ts';
import { tracePixel } from '../../src/tracer/trace-pixel.ts';
import { buildTracerScene } from '../../src/tracer/tracer-scene.ts';
import { DistributionGizmos } from '../../src/view/distribution-gizmos.ts';
import { sceneFrom } from '../support/test-scene.ts';

/** The lens, the plane in focus and the copies in time (distribution-effects §4). */

const drawnBox = new Mesh(new BoxGeometry(1, 1, 1), new MeshBasicMaterial());
const objectOf = () => drawnBox;

function named(gizmos: DistributionGizmos, name: string) {
  const found = gizmos.group.getObjectByName(name);
  if (!found) throw new Error(`no ${name}`);
  return found;
}

describe('distribution gizmos', () => {
  it('draw the lens as a disc of radius aperture at the eye, and the plane in focus at focusDistance along the view', () => {
    const gizmos = new DistributionGizmos();
    gizmos.sync(sceneFrom({ camera: { position: [0, 1, 5], target: [0, 1, 0], aperture: 0.2, focusDistance: 3, pixels: [8, 6], fov: 45 } }), objectOf);
    const lens = named(gizmos, 'lens');
    expect(lens.visible).toBe(true);
    expect(lens.position.toArray()).toEqual([0, 1, 5]);
    expect(lens.scale.x).toBeCloseTo(0.2, 12);
    // The disc faces the view: its local z is along −z here.
    expect(new Vector3(0, 0, 1).applyQuaternion(lens.quaternion).z).toBeCloseTo(1, 12);
    const plane = named(gizmos, 'plane in focus');
    expect(plane.position.z).toBeCloseTo(2, 12);
    // As wide and high as the camera's view at 3 m: 3·tan(22.5°) high per half, 4:3 wide.
    expect(plane.scale.y).toBeCloseTo(3 * Math.tan((22.5 * Math.PI) / 180), 12);
    expect(plane.scale.x / plane.scale.y).toBeCloseTo(8 / 6, 12);
  });

  it('hide the lens and the plane for a pinhole; the plane follows the target when focusDistance is left out', () => {
    const gizmos = new DistributionGizmos();
    gizmos.sync(sceneFrom({}), objectOf);
    expect(named(gizmos, 'lens').visible).toBe(false);
    expect(named(gizmos, 'plane in focus').visible).toBe(false);
    gizmos.sync(sceneFrom({ camera: { position: [0, 0, 4], target: [0, 0, 1], aperture: 0.1 } }), objectOf);
    expect(named(gizmos, 'plane in focus').position.z).toBeCloseTo(1, 12);
  });

  function copiesOf(gizmos: DistributionGizmos, id: string): Mesh[] {
    return named(gizmos, 'copies in time').children.filter((child) => child.name.startsWith(`${id} at`)) as Mesh[];
  }

  const moving = (settings: Record<string, unknown>) =>
    sceneFrom({ settings: { timeSamples: 4, ...settings }, objects: [{ id: 'ball', position: [1, 0.5, 0], velocity: [2, 0, 0] }, { id: 'still' }] });

  it("draw a moving object at the grid's 4 moments, the same for every pixel, with its path", () => {
    const gizmos = new DistributionGizmos();
    gizmos.sync(moving({ timePattern: 'grid' }), objectOf);
    const copies = copiesOf(gizmos, 'ball');
    expect(copies.map((copy) => copy.position.x)).toEqual([1.25, 1.75, 2.25, 2.75]);
    expect(copies.every((copy) => copy.geometry === drawnBox.geometry)).toBe(true);
    expect(named(gizmos, 'path of ball')).toBeDefined();
    expect(gizmos.group.getObjectByName('path of still')).toBeUndefined();
    gizmos.sync(moving({ timePattern: 'grid' }), objectOf, [3, 2]);
    expect(copiesOf(gizmos, 'ball').map((copy) => copy.position.x)).toEqual([1.25, 1.75, 2.25, 2.75]);
  });

  for (const timePattern of ['jittered', 'random'] as const) {
    it(`draw a moving object at the chosen pixel's own moments, its ray tree's (${timePattern})`, () => {
      const gizmos = new DistributionGizmos();
      const scene = moving({ timePattern });
      const tracer = buildTracerScene(scene, new Map());
      for (const pixel of [
        [3, 2],
        [0, 1],
      ] as const) {
        gizmos.sync(scene, objectOf, pixel);
        const moments = tracePixel(tracer, pixel[0], pixel[1], DEFAULT_SEED).rays[0]!.children.map((ray) => ray.time!);
        expect(moments).toHaveLength(4);
        const xs = copiesOf(gizmos, 'ball').map((copy) => copy.position.x);
        expect(xs).toHaveLength(4);
        xs.forEach((x, i) => expect(x).toBeCloseTo(1 + 2 * moments[i]!, 12));
      }
    });
  }

  it('draw one copy where it ends with one time sample, or without a pixel whose moments to show', () => {
    const gizmos = new DistributionGizmos();
    gizmos.sync(moving({ timeSamples: 1, timePattern: 'grid' }), objectOf);
    expect(copiesOf(gizmos, 'ball').map((copy) => copy.position.x)).toEqual([3]);
    gizmos.sync(moving({ timePattern: 'jittered' }), objectOf);
    expect(copiesOf(gizmos, 'ball').map((copy) => copy.position.x)).toEqual([3]);
    expect(named(gizmos, 'path of ball')).toBeDefined();
  });
});
