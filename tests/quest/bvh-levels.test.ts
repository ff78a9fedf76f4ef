import { issueLine } from '../../src/util/issue.ts';
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { initialState } from '../../src/lab-state/lab-state.ts';
import { checkGoal, NO_EVENTS } from '../../src/quest/goal-check.ts';
import { type Level, parseLevelJson } from '../../src/quest/level-schema.ts';
import { loadMeshesFromDisk } from '../../src/scene/load-meshes-node.ts';
import { meshNamesInScene } from '../../src/scene/mesh-names.ts';
import { bvhTree, nodesAtDepth } from '../../src/tracer/bvh-tree.ts';
import { meshAccel } from '../../src/tracer/shapes/mesh-accel.ts';
import { buildTracerScene } from '../../src/tracer/tracer-scene.ts';
import { countPixelTests, type RayTests } from '../../src/tracer/triangle-test-count.ts';

/**
 * The acceleration levels state facts about their scenes: which pixels' rays miss every
 * box, hit the character, test triangles without a hit; how many boxes a depth has. The
 * goals list those pixels by hand, so here every pixel of each screen is traced with the
 * real counter and each goal must accept exactly the pixels the fact is true for.
 */

function readLevel(id: string): Level {
  const parsed = parseLevelJson(readFileSync(new URL(`../../levels/${id}.level.json`, import.meta.url), 'utf8'));
  if (!parsed.ok) throw new Error(parsed.errors.map(issueLine).join('\n'));
  return parsed.level;
}

async function pixelTests(level: Level): Promise<Map<string, RayTests>> {
  const meshes = await loadMeshesFromDisk(meshNamesInScene(level.scene));
  const scene = buildTracerScene(level.scene, meshes);
  const [columns, rows] = level.scene.camera.pixels;
  const tests = new Map<string, RayTests>();
  for (let row = 0; row < rows; row++)
    for (let column = 0; column < columns; column++) tests.set(`${column},${row}`, countPixelTests(scene, meshes, [column, row]));
  return tests;
}

/** The pixels whose selection completes the task's goal. */
function pixelsAccepted(level: Level, taskId: string, all: Iterable<string>): string[] {
  const goal = level.tasks.find((task) => task.id === taskId)!.goal;
  return [...all].filter((key) => {
    const [column, row] = key.split(',').map(Number);
    return checkGoal(goal, { ...initialState(level.scene), selectedPixel: [column, row] }, NO_EVENTS);
  });
}

const where = (tests: Map<string, RayTests>, fact: (test: RayTests) => boolean) => [...tests].filter(([, test]) => fact(test)).map(([key]) => key);
const bounds = (test: RayTests, id: string) => test.objects.find((object) => object.id === id)!.boundsHit;

describe('level 15: bounding boxes', () => {
  const level = readLevel('15-bounding-boxes');

  it('"miss every box" accepts exactly the pixels whose rays miss every bounding box, and they test no triangle', async () => {
    const tests = await pixelTests(level);
    const missAll = where(tests, (test) => test.objects.every((object) => !object.boundsHit));
    expect(missAll.length).toBeGreaterThan(9);
    expect(pixelsAccepted(level, 'miss-every-box', tests.keys())).toEqual(missAll);
    for (const key of missAll) expect(tests.get(key)!.triangles).toBe(0);
  });

  it('"into the character’s box" accepts exactly the pixels whose rays meet the character’s box', async () => {
    const tests = await pixelTests(level);
    expect(pixelsAccepted(level, 'through-character-box', tests.keys())).toEqual(where(tests, (test) => bounds(test, 'hero')));
  });

  it('"a box is only a maybe" accepts exactly the pixels whose rays meet the ball’s box but miss the ball', async () => {
    const tests = await pixelTests(level);
    const maybe = where(tests, (test) => bounds(test, 'ball') && test.hitId !== 'ball');
    expect(maybe.length).toBeGreaterThan(0);
    expect(pixelsAccepted(level, 'box-but-no-ball', tests.keys())).toEqual(maybe);
  });

  it('every ray tests one box per object: the quiz’s answer, 4', async () => {
    const tests = await pixelTests(level);
    expect(level.scene.objects).toHaveLength(4);
    for (const test of tests.values()) expect(test.boundsTests).toBe(4);
  });
});

describe('level 16: the BVH', () => {
  const level = readLevel('16-the-bvh');

  it('"count a ray’s tests" accepts exactly the pixels that show the character, each testing at most a few dozen triangles', async () => {
    const tests = await pixelTests(level);
    const onCharacter = where(tests, (test) => test.hitId === 'hero');
    expect(onCharacter.length).toBeGreaterThan(10);
    expect(pixelsAccepted(level, 'pixel-on-character', tests.keys())).toEqual(onCharacter);
    for (const key of onCharacter) {
      expect(tests.get(key)!.triangles).toBeGreaterThan(0);
      expect(tests.get(key)!.triangles).toBeLessThanOrEqual(48);
      expect(tests.get(key)!.bruteForce).toBe(8624);
    }
  });

  it('"tested, but missed" accepts exactly the pixels whose rays test triangles and hit nothing', async () => {
    const tests = await pixelTests(level);
    const testedButMissed = where(tests, (test) => test.triangles > 0 && test.hitId !== 'hero');
    expect(testedButMissed.length).toBeGreaterThan(0);
    expect(pixelsAccepted(level, 'tested-but-missed', tests.keys())).toEqual(testedButMissed);
  });

  it('the texts’ numbers: 8 boxes at depth 3, leaves at 4 triangles or fewer, 16 levels deep', async () => {
    const meshes = await loadMeshesFromDisk(['character']);
    const tree = bvhTree(meshAccel(meshes.get('character')!).bvh);
    expect(nodesAtDepth(tree, 3)).toHaveLength(8);
    expect(tree.maxDepth).toBe(16);
    expect(nodesAtDepth(tree, tree.maxDepth).every((leaf) => leaf.count <= 4)).toBe(true);
  });
});
