/**
 * A declared view may frame one pixel's rays before the learner picks that pixel: the name
 * `rays:<column>,<row>` stands for that pixel's rays from where its primary ray first hits
 * on, without the camera they start at (docs/levels.md, "Views"). A task that says "select
 * pixel 3,1 and follow its bounces" can so start with the bounces large in view, while the
 * choosing stays the learner's (a view must not do its task's work).
 */
const FRAMED_RAYS = /^rays:(\d+),(\d+)$/;

/** The pixel a framed name `rays:<column>,<row>` names, or null for any other name. */
export function framedRaysPixel(name: string): [number, number] | null {
  const match = FRAMED_RAYS.exec(name);
  return match ? [Number(match[1]), Number(match[2])] : null;
}
