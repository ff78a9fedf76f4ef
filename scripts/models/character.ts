import { BufferGeometry, CapsuleGeometry, CylinderGeometry, Euler, Matrix4, Quaternion, SphereGeometry, Vector3 } from 'three';
import { mergeGeometries } from 'three/examples/jsm/utils/BufferGeometryUtils.js';
import type { ModelRecipe } from './model-recipe.ts';
import { RADIANS_PER_DEGREE } from '../../src/util/angles.ts';

type Triple = [number, number, number];

interface Placement {
  at: Triple;
  /** Euler XYZ in degrees. */
  rotation?: Triple;
  /** Stretches a unit sphere into an ellipsoid. */
  scale?: Triple;
}

/** Moves a part into place; its normals follow (BufferGeometry uses the normal matrix). */
function place(geometry: BufferGeometry, { at, rotation = [0, 0, 0], scale = [1, 1, 1] }: Placement): BufferGeometry {
  const turn = new Quaternion().setFromEuler(new Euler(rotation[0] * RADIANS_PER_DEGREE, rotation[1] * RADIANS_PER_DEGREE, rotation[2] * RADIANS_PER_DEGREE));
  return geometry.applyMatrix4(new Matrix4().compose(new Vector3(...at), turn, new Vector3(...scale)));
}

const ball = (radius: number, detail: number, placement: Placement) => place(new SphereGeometry(radius, 2 * detail, detail), placement);

/** A part on both sides: built for the right (+X) and mirrored for the left. */
function pair(build: (side: 1 | -1) => BufferGeometry): BufferGeometry[] {
  return [build(1), build(-1)];
}

/**
 * A friendly little robot, about 1.08 m tall as built (make-models scales it to 1 m),
 * facing +Z toward the default camera. Every part is a closed shape of its own, so the
 * merged model is closed too; parts overlap, and the hidden surfaces inside do no harm
 * to an opaque object.
 */
function robot(): BufferGeometry {
  const arm = (side: 1 | -1) => place(new CapsuleGeometry(0.04, 0.2, 6, 20), { at: [side * 0.24, 0.47, 0], rotation: [0, 0, side * 25] });
  // The hand sits at the arm's lower end: 0.14 m from its centre along the tilted arm.
  const hand = (side: 1 | -1) =>
    ball(0.055, 10, { at: [side * (0.24 + 0.14 * Math.sin(25 * RADIANS_PER_DEGREE)), 0.47 - 0.14 * Math.cos(25 * RADIANS_PER_DEGREE), 0] });
  const parts = [
    ...pair((side) => ball(1, 10, { at: [side * 0.1, 0.045, 0.02], scale: [0.09, 0.045, 0.13] })), // feet, standing on y = 0
    ...pair((side) => place(new CapsuleGeometry(0.05, 0.16, 6, 20), { at: [side * 0.1, 0.19, 0] })), // legs
    ball(1, 18, { at: [0, 0.45, 0], scale: [0.2, 0.22, 0.16] }), // body
    ball(0.04, 9, { at: [0, 0.5, 0.145] }), // chest light
    ...pair(arm),
    ...pair(hand),
    ball(0.17, 24, { at: [0, 0.8, 0] }), // head
    ...pair((side) => ball(0.035, 10, { at: [side * 0.06, 0.83, 0.145] })), // eyes
    ball(1, 10, { at: [0, 0.74, 0.152], scale: [0.05, 0.015, 0.02] }), // mouth
    ...pair((side) => place(new CylinderGeometry(0.04, 0.04, 0.05, 16), { at: [side * 0.17, 0.8, 0], rotation: [0, 0, 90] })), // ear bolts
    place(new CylinderGeometry(0.012, 0.012, 0.1, 12), { at: [0, 0.99, 0] }), // antenna
    ball(0.03, 9, { at: [0, 1.05, 0] }), // antenna tip
  ];
  const merged = mergeGeometries(parts);
  if (!merged) throw new Error('character: three could not merge the parts (their attributes differ)');
  return merged;
}

export const character: ModelRecipe = {
  name: 'character',
  description: 'a friendly little robot (head with eyes, mouth and antenna, body, arms, legs, feet) facing +Z, smooth normals',
  build: robot,
};
