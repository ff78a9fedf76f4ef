// The acceleration panel's sentences about one ray's tests: they must not contradict each
// other (issue 37: "the BVH skipped 100.0 %" beside 4 triangles tested; "it missed the
// bounding box of every model" beside "went through 1 of them").
import { describe, expect, it } from 'vitest';
import type { ObjectTests, RayTests } from '../../../../src/tracer/triangle-test-count.ts';
import { boxesLine, rayTestsHeadline, skippedPercent } from '../../../../src/ui/lab/panels/bvh-ray-wording.ts';
import { inDutch } from '../../../support/page-locale.ts';

const NAMES: Record<string, string> = { floor: 'Floor', hero: 'Character', ball: 'Red ball' };
const name = (id: string) => NAMES[id] ?? id;

function model(id: string, boundsHit: boolean, triangles: number, bruteForce: number): ObjectTests {
  return { id, boundsHit, mesh: { boxes: boundsHit ? 9 : 0, triangles, bruteForce, t: Infinity, visits: [] } };
}

function rayTests(objects: ObjectTests[]): RayTests {
  const meshes = objects.flatMap((object) => (object.mesh ? [object.mesh] : []));
  return {
    objects,
    boundsTests: objects.length,
    triangles: meshes.reduce((sum, mesh) => sum + mesh.triangles, 0),
    bruteForce: meshes.reduce((sum, mesh) => sum + mesh.bruteForce, 0),
    hitId: null,
  };
}

describe('the share of triangles the BVH skipped', () => {
  it('never reads 100 % while a triangle was tested', () => {
    expect(skippedPercent({ triangles: 4, bruteForce: 8624 })).toBe(99.9);
    expect(skippedPercent({ triangles: 1, bruteForce: 8624 })).toBe(99.9);
    expect(rayTestsHeadline(rayTests([model('hero', true, 4, 8624)]))).toBe('This ray tested 4 of 8,624 triangles: the BVH skipped 99.9\u00a0%.');
  });

  it('is rounded down to a tenth, and is 100 % only when nothing was tested', () => {
    expect(skippedPercent({ triangles: 12, bruteForce: 8624 })).toBe(99.8);
    expect(skippedPercent({ triangles: 1, bruteForce: 3 })).toBe(66.6);
    expect(skippedPercent({ triangles: 3, bruteForce: 3 })).toBe(0);
    expect(skippedPercent({ triangles: 0, bruteForce: 8624 })).toBe(100);
    expect(skippedPercent({ triangles: 0, bruteForce: 0 })).toBe(0);
  });
});

describe('what a ray that missed every model says', () => {
  const floorOnly = rayTests([{ id: 'floor', boundsHit: true, mesh: null }, { id: 'ball', boundsHit: false, mesh: null }, model('hero', false, 0, 8624)]);

  it('says it missed every model, and names the box it did go through', () => {
    expect(rayTestsHeadline(floorOnly)).toBe('This ray tested 0 of 8,624 triangles: it missed the bounding box of every model.');
    expect(boxesLine([1, 7], floorOnly, name)).toBe('Pixel 1, 7: its ray tested 3 bounding boxes (one per object) and went through 1 of them: Floor.');
  });

  it('says "none" when it went through no box at all', () => {
    const sky = rayTests([{ id: 'floor', boundsHit: false, mesh: null }, model('hero', false, 0, 8624)]);
    expect(boxesLine([0, 0], sky, name)).toBe('Pixel 0, 0: its ray tested 2 bounding boxes (one per object) and went through none of them.');
  });
});

describe('a ray into a model', () => {
  it('names every box it went through, in the order they were tested', () => {
    const tests = rayTests([{ id: 'floor', boundsHit: true, mesh: null }, model('hero', true, 12, 8624)]);
    expect(boxesLine([6, 4], tests, name)).toBe('Pixel 6, 4: its ray tested 2 bounding boxes (one per object) and went through 2 of them: Floor, Character.');
    expect(rayTestsHeadline(tests)).toBe('This ray tested 12 of 8,624 triangles: the BVH skipped 99.8\u00a0%.');
  });

  it('says so when the scene has no model', () => {
    expect(rayTestsHeadline(rayTests([{ id: 'ball', boundsHit: true, mesh: null }]))).toBe(
      'No model made of triangles in this scene: this ray tested no triangles.',
    );
  });
});

describe('in Dutch', () => {
  inDutch();

  it('writes the share with a decimal comma, rounded down as well', () => {
    expect(rayTestsHeadline(rayTests([model('hero', true, 4, 8624)]))).toBe('Deze straal testte 4 van de 8.624 driehoeken: de BVH sloeg er 99,9\u00a0% over.');
    const sky = rayTests([{ id: 'floor', boundsHit: false, mesh: null }, model('hero', false, 0, 8624)]);
    expect(boxesLine([0, 0], sky, name)).toBe('Pixel 0, 0: zijn straal testte 2 omhullende dozen (één per object) en ging door geen ervan.');
    const floor = rayTests([{ id: 'floor', boundsHit: true, mesh: null }, model('hero', false, 0, 8624)]);
    expect(boxesLine([1, 7], floor, name)).toBe('Pixel 1, 7: zijn straal testte 2 omhullende dozen (één per object) en ging door 1 ervan: Floor.');
  });
});
