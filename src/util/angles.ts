/**
 * Scene files give angles in degrees (rotations, field of view, spot angles) because people
 * think in them; Math and three.js work in radians. Multiply by these to convert.
 */
export const RADIANS_PER_DEGREE = Math.PI / 180;
export const DEGREES_PER_RADIAN = 180 / Math.PI;
