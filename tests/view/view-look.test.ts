import { BoxGeometry, Mesh, Object3D, Vector3 } from 'three';
import { describe, expect, it } from 'vitest';
import type { Vec3 } from '../../src/scene/scene.ts';
import { framedPoints, LookFollower, PIXEL_RAYS_WAIT_MS, type LookStage } from '../../src/view/view-look.ts';
import { matte, pointLight, sceneFrom } from '../support/test-scene.ts';
import type { ViewPose } from '../../src/view/view-pose.ts';

/** A stage that records where it was sent; the ball is at x = 2, the lamp at y = 4. */
function stage(rays: Vec3[] | null = null) {
  const moves: { pose: ViewPose; glide: boolean }[] = [];
  let throughCamera = 0;
  let pixelRays = rays;
  const here: ViewPose = { position: new Vector3(0, 0, 10), target: new Vector3(), fov: 45 };
  const fake: LookStage = {
    // Pixel 3,1's rays from their first hit: the traced rays but their first point (the camera).
    pointsOf: (name) => ({ ball: [[2, 0, 0]] as Vec3[], lamp: [[0, 4, 0]] as Vec3[], 'rays:3,1': pixelRays?.slice(1) ?? [] })[name] ?? [],
    pixelRayPoints: () => pixelRays,
    pose: () => here,
    fov: 45,
    aspect: () => 1.5,
    visibleShare: () => 1,
    moveTo: (pose, glide) => moves.push({ pose, glide }),
    throughCamera: () => throughCamera++,
  };
  return { fake, moves, setRays: (points: Vec3[]) => (pixelRays = points), throughCamera: () => throughCamera };
}

describe('following a declared look', () => {
  it('frames what it names from the side it names, far enough back to fit them', () => {
    const { fake, moves } = stage();
    new LookFollower(fake).follow({ frame: ['ball', 'lamp'], from: [0, 0, 3] }, true);
    expect(moves).toHaveLength(1);
    const { pose, glide } = moves[0]!;
    expect(glide).toBe(true);
    expect(pose.target.toArray()).toEqual([1, 2, 0]);
    // From +z only: the eye is straight in front of the target.
    expect(pose.position.x).toBeCloseTo(1);
    expect(pose.position.y).toBeCloseTo(2);
    // The two points are √5 from the target: r / sin(22.5°) away.
    expect(pose.position.z).toBeCloseTo(Math.sqrt(5) / Math.sin((22.5 * Math.PI) / 180));
  });

  it('keeps the side it looks from now when the look names none', () => {
    const { fake, moves } = stage();
    new LookFollower(fake).follow({ frame: ['ball'] }, false);
    const { pose, glide } = moves[0]!;
    expect(glide).toBe(false);
    expect(pose.position.x).toBeCloseTo(2);
    expect(pose.position.z).toBeGreaterThan(0);
  });

  it('looks through the camera, and does nothing for an empty look or unknown names', () => {
    const { fake, moves, throughCamera } = stage();
    const follower = new LookFollower(fake);
    follower.follow({ throughCamera: true }, true);
    follower.follow(null, true);
    follower.follow({ frame: ['teapot'] }, true);
    expect(throughCamera()).toBe(1);
    expect(moves).toEqual([]);
  });

  it("frames a pixel's rays when their trace comes in, and again for a newer one, until the learner moves", () => {
    const time = 0;
    const { fake, moves, setRays } = stage();
    const follower = new LookFollower(fake, () => time);
    follower.follow({ frame: ['pixel-rays'] }, true);
    expect(moves).toEqual([]);
    expect(follower.waitingForRays).toBe(true);
    setRays([
      [0, 0, 0],
      [0, 0, -6],
    ]);
    follower.raysArrived();
    setRays([
      [0, 0, 0],
      [0, 0, -8],
    ]);
    follower.raysArrived();
    expect(moves.map((move) => move.pose.target.z)).toEqual([-3, -4]);
    follower.userMoved();
    follower.raysArrived();
    expect(moves).toHaveLength(2);
    expect(follower.waitingForRays).toBe(false);
  });

  it("frames a named pixel's rays after their first hit, chosen or not, waiting for their trace too", () => {
    const { fake, moves, setRays } = stage();
    const follower = new LookFollower(fake, () => 0);
    follower.follow({ frame: ['rays:3,1'] }, true);
    expect(follower.waitingForRays).toBe(true);
    // The camera's end ([0, 0, 10]) is left out: only the bounces are framed.
    setRays([
      [0, 0, 10],
      [0, 0, -6],
      [0, 0, -8],
    ]);
    follower.raysArrived();
    expect(moves.map((move) => move.pose.target.z)).toEqual([-7]);
    follower.follow({ frame: ['rays:0,0'] }, true);
    follower.raysArrived();
    expect(moves).toHaveLength(1);
  });

  it("stops waiting for a pixel's rays after a while", () => {
    let time = 0;
    const { fake, moves, setRays } = stage();
    const follower = new LookFollower(fake, () => time);
    follower.follow({ frame: ['pixel-rays'] }, true);
    time = PIXEL_RAYS_WAIT_MS + 1;
    setRays([
      [0, 0, 0],
      [0, 0, -6],
    ]);
    follower.raysArrived();
    expect(moves).toEqual([]);
    expect(follower.waitingForRays).toBe(false);
  });
});

describe('the points a framed name stands for', () => {
  const scene = sceneFrom({
    camera: { position: [0, 1, 5], target: [0, 0, 0] },
    objects: [{ id: 'ball', shape: 'sphere', position: [2, 0.5, 0], material: matte([1, 0, 0]) }],
    lights: [{ ...pointLight([0, 3, 0]), id: 'spot', type: 'spot', spotAngle: 40 }],
  });
  const cone = new Mesh(new BoxGeometry(1, 1, 1));
  cone.position.set(0, 3.5, 0);
  const drawn = (id: string) => (id === 'spot' ? cone : undefined);

  it("takes a light's drawn shape as well as its place: a spot's cone shows where it points", () => {
    const points = framedPoints('spot', scene, drawn, new Object3D());
    expect(points[0]).toEqual([0, 3, 0]);
    expect(Math.max(...points.map((point) => point[1]))).toBeCloseTo(4);
    expect(points).toHaveLength(9);
  });

  it("falls back to a light's place while it is not drawn, and knows no unknown name", () => {
    expect(framedPoints('spot', scene, () => undefined, new Object3D())).toEqual([[0, 3, 0]]);
    expect(framedPoints('nothing', scene, drawn, new Object3D())).toEqual([]);
  });
});
