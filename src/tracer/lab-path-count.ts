/**
 * How many of a pixel's paths the lab draws and steps through: few enough to follow by eye.
 * A module of its own so that the lab's first screen can name it without loading the tracer.
 */
export const LAB_PATH_COUNT = 8;
